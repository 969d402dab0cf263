/* low.h - a base header that reaches up into the app layer: check_layers.py must refuse it. */
#include "high.h"
