// The sanitizer options every program of the sanitized build starts with (cmake/Reliability.cmake
// compiles this file into each of them; ASAN_OPTIONS, LSAN_OPTIONS and UBSAN_OPTIONS in the
// environment still override them key by key). docs/reliability.md gives the reasons.

// Leak detection on. ASan's __tls_get_addr interception off: clang-14's runtime then guesses the
// bounds of a dynamic TLS block from a glibc 2.19 header that it assumes sits before any block
// starting 16 bytes into a page. A block that PoCL's dlopen'ed libraries get from malloc can start
// there, and LeakSanitizer then scans a made-up range at exit and crashes after the tests have
// passed ("Tracer caught signal 11" in ScanRangeForPointers; LSAN_OPTIONS=log_threads=1 shows
// e.g. "DTLS 35 at 0x2439-0x80000353b").
extern "C" const char* __asan_default_options() {
  return "detect_leaks=1:intercept_tls_get_addr=0";
}

// Without the interception LeakSanitizer does not scan dynamic TLS, where PoCL keeps its
// per-thread LLVM compiler state: when a program compiles a kernel that is not in PoCL's cache,
// those blocks look unreachable at exit. Only allocations with a PoCL or LLVM frame are
// suppressed; penumbra's own code never allocates through them.
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libpocl.so\n"
         "leak:libLLVM-15.so\n";
}

extern "C" const char* __ubsan_default_options() {
  return "print_stacktrace=1";
}
