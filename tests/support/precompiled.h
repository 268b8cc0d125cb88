#pragma once
// What nearly every suite includes, compiled once per kind of suite (tests/CMakeLists.txt). Qt Test's
// header brings its widget and GUI helpers in the suites that link them.

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
