# Empties a fuzz target's work corpus before its ctest run (tests/fuzz/CMakeLists.txt), so every
# run starts where the CI smoke starts.
file(REMOVE_RECURSE ${DIR})
file(MAKE_DIRECTORY ${DIR})
