// placeholder so the library has a source until the modules land
#include "spline/types.h"
