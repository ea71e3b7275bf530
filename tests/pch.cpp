// Compiles nothing itself: the source the tests' shared precompiled header is built beside.
