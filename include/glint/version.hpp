// glint version. Kept in step with project(VERSION) in CMakeLists.txt (a test checks it).
#pragma once

#define GLINT_VERSION_MAJOR 0
#define GLINT_VERSION_MINOR 1
#define GLINT_VERSION_PATCH 0
#define GLINT_VERSION_STRING "0.1.0"
