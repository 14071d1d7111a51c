// The translation unit that makes a test kind's precompiled header (tests/CMakeLists.txt); it
// holds nothing itself.
#include "TestPrecompiled.h"
