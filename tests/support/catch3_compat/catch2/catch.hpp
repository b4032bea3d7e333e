#pragma once
// Catch2 3 (vcpkg on Windows) under the Catch2 2.13 include the suites use (Debian).
#include <catch2/catch_all.hpp>
using Catch::Approx;
