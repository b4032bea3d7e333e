// Precompiled once for every Catch2 suite of a build (tests/CMakeLists.txt, stepwise_test_pch):
// Catch2's single header, the standard headers and the engine's common headers (Eigen through
// math/math.h) that most suites include. Parsing them is a third to a half of compiling a small
// suite; every suite's own includes still name what it uses, so a suite compiles without this.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "app/runner.h"
#include "math/random.h"
#include "world/report.h"
#include "world/state_hash.h"
