// Entry point of the SystemC test programs: libsystemc's main() calls this sc_main, which runs
// GoogleTest (linking GTest::gtest_main instead would bypass sc_main). The trirast CLI, by
// contrast, has its own main() and relies on the weak sc_main stub in model/common/sc_engine.cpp.
#include <gtest/gtest.h>

#include <systemc>

int sc_main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
