// Linked into every test program, and into the programs in sanitizer builds (apps/). Under
// -DTISSU_SANITIZE=ON: Mesa's OSMesa keeps a few hundred bytes per context it made (allocated in
// OSMesaMakeCurrent) until the process ends; they are not tissu's leaks, and any test that renders
// would otherwise fail LeakSanitizer.
extern "C" const char* __lsan_default_suppressions() {
  return "leak:libOSMesa.so\n";
}

// Not the list of suppressions used at exit either: the programs' stderr is checked to be one
// line on refused input (tests/apps/*.sh), in sanitizer builds too.
extern "C" const char* __lsan_default_options() {
  return "print_suppressions=0";
}
