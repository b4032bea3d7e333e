// The target that owns the suites' precompiled header (tests/CMakeLists.txt); no code of its own.
