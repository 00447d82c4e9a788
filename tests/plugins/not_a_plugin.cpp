// A shared library that is not a piezocontact plugin (no entry points): loading it must be refused.
extern "C" __attribute__((visibility("default"))) int some_function() { return 42; }
