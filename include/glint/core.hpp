// glint core numerics: hashing, uniform variates, erfinv, the normal quantile, (1 - p)^N.
#pragma once

#include "glint/core/error.hpp"
#include "glint/core/hash.hpp"
#include "glint/core/normal.hpp"
#include "glint/core/pow_one_minus.hpp"
#include "glint/version.hpp"
