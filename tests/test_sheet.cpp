#include <gtest/gtest.h>

#include "engine/geometry/validate.hpp"

TEST(Sheet, Placeholder) {}
