#include "editor/lightproperty.h"
