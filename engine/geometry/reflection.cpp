#include "engine/geometry/reflection.hpp"
