// The tests' main(). As the mistfall command does (cli/openmp_runtime.hpp), it shortens libgomp's idle spin unless
// the user set one: with libgomp's long default a test's second thread spins on the core a simulation running beside
// it needs, and the tests run several times slower (measured: README.md, `make test`).
#include <gtest/gtest.h>

#include "cli/openmp_runtime.hpp"

int main(int argc, char** argv) {
  mistfall::useShortOpenMpSpin(argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
