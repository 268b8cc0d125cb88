#pragma once
// What nearly every suite includes, compiled once per kind of suite (tests/CMakeLists.txt). Qt Test's
// header brings its widget and GUI helpers in the suites that link them. nlohmann-json is not here:
// six suites use it, and in the other sixty it made each compile a quarter slower (a small suite's
// 2.3 s against 1.75 s, the header 261 MB against 223 MB).

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>
