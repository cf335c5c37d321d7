#include "pipeline/version.h"

namespace tessref {
const char* version() { return "0.1.0"; }
}  // namespace tessref
