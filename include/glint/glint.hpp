// All of glint's C++ headers that need no optional dependency. glint/glsl.hpp (the kernel texts)
// and glint/io/ are included separately.
#pragma once

#include "glint/core.hpp"
