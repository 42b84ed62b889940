// A plug-in (include/exactccd/plugin.h) that exports only exactccd_plugin_vf: CTest checks
// that `exactccd fuzz-against --kind ee` rejects it with an error naming the missing symbol.
#include "exactccd/plugin.h"

extern "C" EXACTCCD_PLUGIN_EXPORT int exactccd_plugin_vf(const double q[24]) {
  return q[0] == q[12] ? 1 : 0;  // any answer: this plug-in only tests the loader
}
