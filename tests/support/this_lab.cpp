// Compiled into each lab's test executable (tests/labs/CMakeLists.txt) with
// FW_LAB_DIR set to that lab's folder: what "this lab" means for its test.
#include "tests/support/test_support.hpp"

namespace fw::test {

const RegisteredLab& this_lab() { return find_lab_in_folder(FW_LAB_DIR); }

LabUnderTest::LabUnderTest() : LabUnderTest(this_lab()) {}

}  // namespace fw::test
