// glint_normal_map: writes one of glint's procedural normal maps (glint/patterns.hpp) as a
// 32-bit float OpenEXR file and a 16-bit PNG (OpenGL convention: green = +y up the image).
//
//   glint_normal_map --pattern brushed|noise|anisotropic_noise|flakes|pyramids|scratches|leather|scratched_metal|sinusoid|flat|tilt|ramp
//                    [--size WxH] [--seed N] [--slope S] [--feature F] [--count N] [--out PATH.exr]
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include <glint/io/normal_map.hpp>
#include <glint/patterns.hpp>

#include "support/cli.hpp"

using namespace glint_examples;

namespace {

[[noreturn]] void usage(const std::string& problem) {
    std::fprintf(stderr,
                 "glint_normal_map: %s\n"
                 "usage: glint_normal_map --pattern NAME [--size WxH] [--seed N] [--slope S] [--feature F] [--count N] [--out PATH.exr]\n",
                 problem.c_str());
    std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
    glint::pattern_params p;
    p.width = p.height = 256;
    std::string out, pattern;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&] { return flag_value(argc, argv, i, usage); };
        if (a == "--pattern") pattern = value();
        else if (a == "--size") parse_size(a, value(), p.width, p.height, usage);
        else if (a == "--seed") p.seed = static_cast<std::uint32_t>(parse_float(a, value(), 0, 4e9f, usage));
        else if (a == "--slope") p.slope_rms = static_cast<double>(parse_float(a, value(), 1e-4f, 1, usage));
        else if (a == "--feature") p.feature = static_cast<double>(parse_float(a, value(), 1, 4096, usage));
        else if (a == "--count") p.count = static_cast<int>(parse_float(a, value(), 0, 1e6f, usage));
        else if (a == "--out") out = parse_exr_path(a, value(), usage);
        else if (a == "--help" || a == "-h") usage("writes a procedural normal map");
        else usage("unknown option '" + a + "'");
    }
    if (pattern.empty()) usage("--pattern is required");
    try {
        p.kind = glint::parse_pattern(pattern);
        if (out.empty()) out = pattern + ".exr";
        const glint::normal_map m = glint::make_normal_map(p);
        glint::io::write_normal_map(out, m);
        const std::string png = out.substr(0, out.size() - 4) + ".png";
        glint::io::write_normal_map(png, m);
        std::printf("wrote %s and %s (%d x %d, %s)\n", out.c_str(), png.c_str(), p.width, p.height, pattern.c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "glint_normal_map: %s\n", e.what());
        return 1;
    }
    return 0;
}
