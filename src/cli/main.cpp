#include "Commands.h"
int main() { return 0; }
