#include <cstdio>
int main() {
  std::puts("pdq");
  return 0;
}
