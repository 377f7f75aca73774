#include "engine/model.hpp"

namespace pdq {

template <>
Registry<ModelFactory>::Table& Registry<ModelFactory>::table() {
  static Table t{"model"};
  return t;
}

}  // namespace pdq
