// An outside program that uses glint: C++ kernels, the embedded GLSL, and (when found through
// find_package) the installed kernel folder.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include <glint/glint.hpp>
#include <glint/glsl.hpp>

int main() {
    const float z = glint::normal_quantile(0.975f);
    if (std::fabs(z - 1.959964f) > 1e-5f) {
        std::printf("normal_quantile(0.975) = %.7f, expected 1.959964\n", static_cast<double>(z));
        return 1;
    }
    const std::string core(glint::glsl_source("core.glsl"));
    if (core.find("glint_pcg3d") == std::string::npos) {
        std::printf("glsl_source(\"core.glsl\") lacks glint_pcg3d\n");
        return 1;
    }
#ifdef GLINT_GLSL_DIR
    std::ifstream installed(std::string(GLINT_GLSL_DIR) + "/core.glsl");
    std::string text((std::istreambuf_iterator<char>(installed)), std::istreambuf_iterator<char>());
    if (text != core) {
        std::printf("installed %s/core.glsl differs from glsl_source(\"core.glsl\")\n", GLINT_GLSL_DIR);
        return 1;
    }
#endif
    std::printf("glint %s consumer OK\n", GLINT_VERSION_STRING);
    return 0;
}
