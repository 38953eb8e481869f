// What nearly every test includes, parsed once per test binary into a precompiled header
// (CMakeLists.txt: the tests are two thirds of a fresh build, issue 28). The pragma: see
// src/core/precompiled.h.
#pragma once
#pragma GCC system_header

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/precompiled.h"
