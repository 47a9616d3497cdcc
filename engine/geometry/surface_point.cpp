#include "engine/geometry/surface_point.hpp"
