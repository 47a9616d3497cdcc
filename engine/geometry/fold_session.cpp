#include "engine/geometry/fold_session.hpp"
