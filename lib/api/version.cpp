// exactccd_version() (exactccd/exactccd.h): the library's version as built, the CMake project
// version (the same string as exactccd/version.h, `exactccd --version` and the Python
// module's __version__ and package metadata).
#include "exactccd/exactccd.h"
#include "exactccd/version.h"

extern "C" const char* exactccd_version(void) { return EXACTCCD_VERSION_STRING; }
