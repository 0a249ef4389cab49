// All of glint's C++ headers that need no optional dependency. glint/glsl.hpp (the kernel texts)
// and glint/io/ are included separately.
#pragma once

#include "glint/core.hpp"
#include "glint/binomial.hpp"
#include "glint/multinomial.hpp"
#include "glint/microfacet.hpp"
#include "glint/grid.hpp"
#include "glint/ibl.hpp"
#include "glint/normal_map.hpp"
#include "glint/patterns.hpp"
#include "glint/gaussian.hpp"
#include "glint/scratch.hpp"
#include "glint/ndf_map.hpp"
#include "glint/bin_map.hpp"
#include "glint/lobe_tree.hpp"
