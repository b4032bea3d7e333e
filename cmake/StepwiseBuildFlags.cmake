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
