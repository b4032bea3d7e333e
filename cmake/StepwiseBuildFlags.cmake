# Flags that hold for every target of the build (stepwise_set_warnings adds the per-target
# warning flags). Two concerns live here: floating-point determinism and the sanitizers.

# Determinism. The same source must round the same way on every compiler this project builds
# with (GCC, Clang, mingw-w64, MSVC): no fast-math anywhere, and no contraction of a*b+c into a
# fused multiply-add, whose single rounding differs from two. FMA contraction is the usual cause
# of results that drift between compilers or -march settings; Box3D builds with
# -ffp-contract=off for the same reason. MSVC's /fp:precise is its default and does not contract
# across statements; it is spelled out so that no toolchain file can slip /fp:fast in.
if(MSVC)
  add_compile_options(/fp:precise)
else()
  add_compile_options(-ffp-contract=off -fno-fast-math)
  # 32-bit x86 computes in the x87 unit by default, whose 80-bit registers round when the compiler
  # spills them, so results follow register allocation; SSE2 rounds every operation to its type
  # (FLT_EVAL_METHOD 0, as on every x86-64 build). tests/reliability/float_env_test.cpp checks it.
  if(CMAKE_SIZEOF_VOID_P EQUAL 4 AND CMAKE_SYSTEM_PROCESSOR MATCHES "^(i[3-6]86|x86)$")
    add_compile_options(-msse2 -mfpmath=sse)
  endif()
endif()

# The linker: -DSTEPWISE_LINKER=lld in the Linux presets (Debian's lld, tools/setup-deps.sh), which
# links a test program in a third of the time GNU ld takes (a sanitizer build's in 1 s instead of
# 3). Where the compiler cannot link with it (lld not installed, MSVC) the build says so and keeps
# the compiler's default linker. Empty: the compiler's default linker.
set(STEPWISE_LINKER "" CACHE STRING "Linker for GCC and Clang (-fuse-ld=), e.g. lld; empty: the compiler's default")
if(STEPWISE_LINKER AND NOT MSVC)
  include(CheckLinkerFlag)
  string(MAKE_C_IDENTIFIER "STEPWISE_LINKER_${STEPWISE_LINKER}_WORKS" linker_check)
  check_linker_flag(CXX -fuse-ld=${STEPWISE_LINKER} ${linker_check})
  if(${linker_check})
    add_link_options(-fuse-ld=${STEPWISE_LINKER})
  else()
    message(STATUS "STEPWISE_LINKER=${STEPWISE_LINKER}: the compiler cannot link with it; using its default linker")
  endif()
endif()

# Sanitizers: -DSTEPWISE_SANITIZE=address,undefined (the linux-asan preset). Any report ends the
# program (no recover), so a ctest run fails on the first finding.
set(STEPWISE_SANITIZE "" CACHE STRING "Sanitizers to build with, e.g. address,undefined")
if(STEPWISE_SANITIZE)
  if(MSVC)
    message(FATAL_ERROR "STEPWISE_SANITIZE is for GCC and Clang")
  endif()
  add_compile_options(-fsanitize=${STEPWISE_SANITIZE} -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${STEPWISE_SANITIZE})
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    # GCC 12's -Wmaybe-uninitialized reports false positives inside libstdc++ (<regex>, <variant>)
    # once the sanitizers' instrumentation changes what its flow analysis sees; GCC's manual
    # warns that sanitizer builds make such warnings unreliable. Reported, not fatal, and only
    # here: the plain builds keep the warning as an error.
    add_compile_options(-Wno-error=maybe-uninitialized)
  endif()
endif()

# Fuzzing: -DSTEPWISE_FUZZ=ON (the linux-asan preset) builds tests/fuzz as libFuzzer programs.
# Every target gets libFuzzer's coverage instrumentation (fuzzer-no-link), so the engine's own
# branches guide the fuzzer; only the fuzz programs link libFuzzer's main. Without it the same
# sources build as plain programs that replay the seed corpus and the regression inputs.
option(STEPWISE_FUZZ "Build tests/fuzz with Clang's libFuzzer (needs Clang)" OFF)
if(STEPWISE_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "STEPWISE_FUZZ needs Clang (libFuzzer), e.g. -DCMAKE_CXX_COMPILER=clang++; "
                        "Debian: apt-get install clang libclang-rt-dev")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
# The chapters' libraries, the physics, keep the coverage counters but not trace-cmp, which calls
# into libFuzzer at every integer comparison so that it can learn the values an input must match
# (the JSON reader's keys and numbers, in common/, keep it). The physics compares floats, which
# trace-cmp does not see; what it traced there was mostly the sanitizers' own alignment and bounds
# checks and Eigen's index asserts (perf, bench speed's pile under the sanitizers: 15.7% of the
# time in __sanitizer_cov_trace_*, called from Aabb::overlaps, the support points, the wide solve),
# no value an input could be made to match.
function(stepwise_chapter_code target)
  if(STEPWISE_FUZZ)
    target_compile_options(${target} PRIVATE -fno-sanitize-coverage=trace-cmp)
  endif()
endfunction()

# The test programs' own code: -DSTEPWISE_TEST_OPTIMIZATION=-Og (the Linux presets). The Catch2
# suites, their main, the scenario promises, the exercise checks and the CLI and PNG checkers call
# the engine; the engine's libraries keep the build type's flags, so the engine runs (and rounds:
# no fast-math, no contraction at any level) exactly as in the demos and the benches. The suites'
# own code, assertions and scene set-up, is two fifths of a build's compiling; -Og takes a fifth
# off its code generation and runs the suites as fast as -O3 does. -O0 would compile faster
# still, but the engine's inline functions instantiated in a suite then run several times slower
# (chapter 6's suite: 2.6 times). Empty: the build type's flags everywhere. GCC and Clang take the
# last -O on the line.
set(STEPWISE_TEST_OPTIMIZATION "" CACHE STRING
    "Optimisation flag for the test programs' own code (e.g. -Og); empty: the build type's")
function(stepwise_test_code target)
  if(STEPWISE_TEST_OPTIMIZATION AND NOT MSVC)
    target_compile_options(${target} PRIVATE ${STEPWISE_TEST_OPTIMIZATION})
  endif()
  if(STEPWISE_FUZZ)
    # libFuzzer's coverage guides the fuzz programs; a test program never runs libFuzzer, so its
    # own code needs none (its sanitizers stay).
    get_target_property(options ${target} COMPILE_OPTIONS)
    list(REMOVE_ITEM options -fsanitize=fuzzer-no-link)
    set_target_properties(${target} PROPERTIES COMPILE_OPTIONS "${options}")
  endif()
endfunction()
