#include "WorldIO.h"
