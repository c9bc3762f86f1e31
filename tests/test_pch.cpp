// The translation unit that makes the test executables' shared
// precompiled header (tests/CMakeLists.txt); it holds no test.
