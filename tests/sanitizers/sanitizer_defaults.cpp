/// \file sanitizer_defaults.cpp
/// Default options of the sanitiser runtimes, linked into every executable of a build configured
/// with SYMCONTACT_SANITIZE (CMakeLists.txt), so that the tests, the gtest discovery at build time,
/// the command-line program the CLI tests start and a run by hand all behave alike without any
/// environment variable:
///
/// - LeakSanitizer reads the suppressions of third-party leaks in tests/sanitizers/lsan.supp
///   (SYMCONTACT_LSAN_SUPPRESSIONS, an absolute path set by CMake);
/// - UndefinedBehaviorSanitizer prints a stack and halts (the code is also built with
///   -fno-sanitize-recover=all, so any report is a failure).
///
/// Options given in ASAN_OPTIONS, LSAN_OPTIONS or UBSAN_OPTIONS are applied after these and win.

extern "C" {

const char* __lsan_default_options() { return "suppressions=" SYMCONTACT_LSAN_SUPPRESSIONS ":print_suppressions=0"; }

const char* __ubsan_default_options() { return "print_stacktrace=1:halt_on_error=1"; }

const char* __asan_default_options() { return "detect_stack_use_after_return=0:strict_string_checks=1"; }

}  // extern "C"
