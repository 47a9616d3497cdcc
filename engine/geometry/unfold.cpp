#include "engine/geometry/unfold.hpp"
