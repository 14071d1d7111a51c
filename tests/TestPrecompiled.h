// What nearly every test file includes, parsed once per test folder instead of once per file
// (tests/CMakeLists.txt): QtTest, Eigen and the standard library were two thirds of a test
// file's compile time (TestControl.cpp 12.0 s of CPU without, 5.8 s with; docs/build-speed.md).
#pragma once

#include <Eigen/Dense>
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>
