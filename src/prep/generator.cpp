#include "prep/generator.hpp"

namespace pdq {

template <>
Registry<Generator>::Table& Registry<Generator>::table() {
  static Table t{"generator"};
  return t;
}

}  // namespace pdq
