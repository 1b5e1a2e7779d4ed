#include "Svg.h"
