/* high.h - an app header including one below it: allowed. */
#include "low.h"
