// glint::io::read_exr / write_exr: the five environment maps, a round trip, and every bad input
// the loader must reject with a message that names the file and the problem.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>

#include <glint/io/exr.hpp>

#ifndef GLINT_DATA_DIR
#error "GLINT_DATA_DIR must point at the project's data/ folder"
#endif

namespace {

std::string temp_path(const std::string& name) { return std::string(GLINT_TEST_TMP_DIR) + "/" + name; }

// The message of the glint::error `f` throws ("" if it throws none).
template <class F>
std::string error_of(F f) {
    try {
        f();
    } catch (const glint::error& e) {
        return e.what();
    }
    return "";
}

double luminance(const glint::io::rgb_image& img, std::size_t i) {
    return 0.2126 * static_cast<double>(img.rgb[3 * i]) + 0.7152 * static_cast<double>(img.rgb[3 * i + 1]) + 0.0722 * static_cast<double>(img.rgb[3 * i + 2]);
}

}  // namespace

TEST_CASE("exr: the five environment maps read as 1024 x 512, finite and non-negative, with their documented peaks") {
    const std::pair<const char*, double> maps[] = {{"city", 31749}, {"courtyard", 52.9}, {"interior", 32216}, {"studio", 110.9}, {"sunset", 2090}};
    for (const auto& [name, peak] : maps) {
        const auto img = glint::io::read_exr(std::string(GLINT_DATA_DIR) + "/envmaps/" + name + ".exr");
        CHECK(img.width == 1024);
        CHECK(img.height == 512);
        double max_y = 0;
        bool finite = true;
        for (std::size_t i = 0; i < img.rgb.size() / 3; ++i) max_y = std::max(max_y, luminance(img, i));
        for (float v : img.rgb) finite = finite && std::isfinite(v) && v >= 0;
        MESSAGE(std::string(name) << ": peak luminance " << max_y << ", " << img.clamped << " pixels clamped");
        CHECK(finite);
        CHECK(max_y == doctest::Approx(peak).epsilon(0.01));
    }
}

TEST_CASE("exr: write then read returns the pixels within half precision, negative and non-finite pixels read as 0 and are counted") {
    const int w = 7, h = 3;
    std::vector<float> rgb(3 * w * h);
    for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = std::pow(10.0f, static_cast<float>(i % 9) - 4.0f) * 1.37f;
    rgb[4] = -0.5f;
    rgb[10] = std::numeric_limits<float>::infinity();
    rgb[20] = std::numeric_limits<float>::quiet_NaN();
    const std::string path = temp_path("glint_roundtrip.exr");
    glint::io::write_exr(path, w, h, rgb);
    const auto img = glint::io::read_exr(path);
    REQUIRE(img.width == w);
    REQUIRE(img.height == h);
    CHECK(img.clamped == 3u);
    for (std::size_t i = 0; i < rgb.size(); ++i) {
        if (i == 4 || i == 10 || i == 20) {
            CHECK(img.rgb[i] == 0.0f);
        } else {
            CHECK(std::fabs(img.rgb[i] - rgb[i]) <= 1e-3f * rgb[i]);  // half float: 11-bit significand
        }
    }
}

TEST_CASE("exr: a missing file, a file that is not EXR, an image without R, G, B, and an empty image are rejected by name") {
    const std::string missing = temp_path("glint_no_such_file.exr");
    std::string m = error_of([&] { glint::io::read_exr(missing); });
    CHECK(m.find(missing) != std::string::npos);

    const std::string text = temp_path("glint_not_exr.exr");
    std::ofstream(text) << "this is not an OpenEXR file\n";
    m = error_of([&] { glint::io::read_exr(text); });
    CHECK(m.find(text) != std::string::npos);

    // A luminance-only (Y) image.
    const std::string y_only = temp_path("glint_y_only.exr");
    {
        Imf::Header header(4, 2);
        header.channels().insert("Y", Imf::Channel(Imf::FLOAT));
        std::vector<float> y(8, 1.0f);
        Imf::OutputFile file(y_only.c_str(), header);
        Imf::FrameBuffer fb;
        fb.insert("Y", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(y.data()), sizeof(float), 4 * sizeof(float)));
        file.setFrameBuffer(fb);
        file.writePixels(2);
    }
    m = error_of([&] { glint::io::read_exr(y_only); });
    MESSAGE(m);
    CHECK(m.find(y_only) != std::string::npos);
    CHECK(m.find("no channel R, G, B") != std::string::npos);
    CHECK(m.find("channels: Y") != std::string::npos);

    m = error_of([&] { glint::io::write_exr(temp_path("glint_empty.exr"), 0, 5, {}); });
    CHECK(m.find("empty") != std::string::npos);
    m = error_of([&] { glint::io::write_exr(temp_path("glint_short.exr"), 2, 2, std::vector<float>(5)); });
    CHECK(m.find("5 floats") != std::string::npos);
}
