// Normal-map files: EXR and PNG round trips, the green-channel conventions, height maps, every
// bad-input error, and a bounded mutation fuzz of both readers (libFuzzer-style mutations of a
// small corpus, 44000 inputs in all: the readers must return a map or throw glint::error, nothing
// else; the ASan + UBSan build of this test checks for memory errors and leaks).
#include <doctest/doctest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include <zlib.h>

#include <glint/core/hash.hpp>
#include <glint/io/normal_map.hpp>
#include <glint/patterns.hpp>

#include "../support/errors.hpp"

namespace {

const std::string tmp = GLINT_TEST_TMP_DIR;

using glint_test::contains;
using glint_test::error_of;

std::vector<std::uint8_t> read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::vector<std::uint8_t>((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void write_bytes(const std::string& path, const std::vector<std::uint8_t>& b) {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
}

// Sets a big-endian 32-bit word and re-computes the CRC of the chunk that starts at `chunk`.
void patch_png_chunk(std::vector<std::uint8_t>& b, std::size_t chunk, std::size_t offset, std::uint32_t value) {
    for (int k = 0; k < 4; ++k) b[chunk + 8 + offset + static_cast<std::size_t>(k)] = static_cast<std::uint8_t>(value >> (24 - 8 * k));
    const std::uint32_t length = (static_cast<std::uint32_t>(b[chunk]) << 24) | (static_cast<std::uint32_t>(b[chunk + 1]) << 16) |
                                 (static_cast<std::uint32_t>(b[chunk + 2]) << 8) | b[chunk + 3];
    const auto crc = static_cast<std::uint32_t>(crc32(0, b.data() + chunk + 4, static_cast<uInt>(length + 4)));
    for (int k = 0; k < 4; ++k) b[chunk + 8 + length + static_cast<std::size_t>(k)] = static_cast<std::uint8_t>(crc >> (24 - 8 * k));
}

glint::normal_map test_map() {
    glint::pattern_params p;
    p.kind = glint::pattern::leather;
    p.width = 24, p.height = 16;
    p.slope_rms = 0.4;
    return glint::make_normal_map(p);
}

}  // namespace

TEST_CASE("normal-map files: EXR and PNG round trips, green conventions, height maps") {
    const glint::normal_map m = test_map();
    for (const auto green : {glint::io::green_axis::up, glint::io::green_axis::down}) {
        glint::io::normal_map_read_options o;
        o.green = green;
        glint::io::write_normal_map(tmp + "/nm.exr", m, green);
        glint::io::write_normal_map(tmp + "/nm.png", m, green);
        const glint::normal_map e = glint::io::read_normal_map(tmp + "/nm.exr", o), p = glint::io::read_normal_map(tmp + "/nm.png", o);
        REQUIRE(e.width() == 24);
        REQUIRE(p.height() == 16);
        float worst_e = 0, worst_p = 0;
        for (std::size_t i = 0; i < m.normals().size(); ++i) {
            worst_e = std::max(worst_e, glm::length(e.normals()[i] - m.normals()[i]));
            worst_p = std::max(worst_p, glm::length(p.normals()[i] - m.normals()[i]));
        }
        CHECK(worst_e < 1e-6f);  // float channels, renormalised
        CHECK(worst_p < 5e-5f);  // 16 bits per component
        // Read with the other convention: y flips.
        o.green = green == glint::io::green_axis::up ? glint::io::green_axis::down : glint::io::green_axis::up;
        const glint::normal_map f = glint::io::read_normal_map(tmp + "/nm.exr", o);
        CHECK(f.normals()[5].y == doctest::Approx(-m.normals()[5].y).epsilon(1e-6));
        CHECK(f.normals()[5].x == doctest::Approx(m.normals()[5].x).epsilon(1e-6));
    }
    // The OpenGL convention stores +y up the image: a normal leaning towards row 0 (y < 0 in
    // glint's frame) has green above 1/2.
    std::vector<std::uint16_t> px(3 * 4, 0);
    for (int i = 0; i < 4; ++i) px[3 * static_cast<std::size_t>(i)] = 128, px[3 * static_cast<std::size_t>(i) + 1] = 200, px[3 * static_cast<std::size_t>(i) + 2] = 230;
    glint::io::write_png(tmp + "/up.png", 2, 2, 3, 8, px);
    const glint::normal_map up = glint::io::read_normal_map(tmp + "/up.png");
    CHECK(up.texel(0, 0).y < 0);
    CHECK(std::fabs(up.texel(0, 0).x) < 0.01f);
    // 8-bit: within 1/255 per component before renormalising.
    // A height map: a gray ramp along x, 1/255 per texel times the scale 255 -> slope 1 (45 degrees).
    std::vector<std::uint16_t> gray(8 * 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 8; ++x) gray[static_cast<std::size_t>(x + 8 * y)] = static_cast<std::uint16_t>(10 + x);
    glint::io::write_png(tmp + "/height.png", 8, 3, 1, 8, gray);
    const glint::normal_map h = glint::io::read_height_map(tmp + "/height.png", 255.0f, {glint::wrap_mode::clamp});
    CHECK(h.texel(3, 1).x == doctest::Approx(-std::sqrt(0.5)).epsilon(1e-5));
    CHECK(h.texel(3, 1).y == doctest::Approx(0).epsilon(1e-6));
}

TEST_CASE("normal-map files: every bad input raises glint::error naming the file and the problem") {
    CHECK(contains(error_of([] { glint::io::read_normal_map(tmp + "/missing.png"); }), "missing.png: cannot open the file"));
    CHECK(contains(error_of([] { glint::io::read_normal_map(tmp + "/missing.exr"); }), "missing.exr"));
    CHECK(contains(error_of([] { glint::io::read_normal_map(tmp + "/map.tga"); }), "map.tga: unknown file type (.exr or .png)"));
    const glint::normal_map m = test_map();
    glint::io::write_normal_map(tmp + "/good.png", m);
    const std::vector<std::uint8_t> good = read_bytes(tmp + "/good.png");
    // Truncated, corrupted (a CRC no longer matches), not a PNG at all.
    write_bytes(tmp + "/truncated.png", std::vector<std::uint8_t>(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(good.size() / 2)));
    CHECK(contains(error_of([] { glint::io::read_normal_map(tmp + "/truncated.png"); }), "truncated.png: "));
    std::vector<std::uint8_t> bad = good;
    bad[bad.size() / 2] ^= 0x5a;
    write_bytes(tmp + "/corrupt.png", bad);
    CHECK(contains(error_of([] { glint::io::read_normal_map(tmp + "/corrupt.png"); }), "corrupt.png: "));
    write_bytes(tmp + "/text.png", {'h', 'e', 'l', 'l', 'o', ' ', 'w', 'o', 'r', 'l', 'd'});
    CHECK(contains(error_of([] { glint::io::read_normal_map(tmp + "/text.png"); }), "text.png: not a PNG file (bad signature)"));
    // Zero width in a well-formed header (CRC recomputed): libpng's own check.
    bad = good;
    patch_png_chunk(bad, 8, 0, 0);
    write_bytes(tmp + "/zero.png", bad);
    const std::string zero = error_of([] { glint::io::read_normal_map(tmp + "/zero.png"); });
    MESSAGE("zero width: " << zero);
    CHECK(contains(zero, "zero.png: "));
    CHECK(contains(zero, "width"));
    // Wrong channel count: a gray PNG; an EXR without B.
    glint::io::write_png(tmp + "/gray.png", 2, 2, 1, 8, {1, 2, 3, 4});
    CHECK(contains(error_of([] { glint::io::read_normal_map(tmp + "/gray.png"); }), "gray.png: 1 channels; a normal map needs RGB or RGBA"));
    {
        Imf::Header header(2, 2);
        header.channels().insert("R", Imf::Channel(Imf::FLOAT));
        header.channels().insert("G", Imf::Channel(Imf::FLOAT));
        std::vector<float> v(8, 0.5f);
        Imf::FrameBuffer fb;
        fb.insert("R", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(v.data()), 2 * sizeof(float), 4 * sizeof(float)));
        fb.insert("G", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(v.data() + 1), 2 * sizeof(float), 4 * sizeof(float)));
        Imf::OutputFile f((tmp + "/rg.exr").c_str(), header);
        f.setFrameBuffer(fb);
        f.writePixels(2);
    }
    CHECK(contains(error_of([] { glint::io::read_normal_map(tmp + "/rg.exr"); }), "rg.exr: no channel B (channels: G, R)"));
    // Non-finite texels, and z <= 0.
    glint::io::write_exr(tmp + "/nan.exr", 2, 1, {0, 0, 1, 0, std::nanf(""), 1}, true);
    CHECK(contains(error_of([] { glint::io::read_normal_map(tmp + "/nan.exr"); }), "nan.exr: texel (1, 0)"));
    CHECK(contains(error_of([] { glint::io::read_normal_map(tmp + "/nan.exr"); }), "is not finite"));
    glint::io::write_png(tmp + "/below.png", 2, 1, 3, 8, {128, 128, 255, 200, 128, 100});
    CHECK(contains(error_of([] { glint::io::read_normal_map(tmp + "/below.png"); }), "below.png: texel (1, 0)"));
    glint::io::normal_map_read_options o;
    o.map.clamp_z = true;
    const glint::normal_map clamped = glint::io::read_normal_map(tmp + "/below.png", o);
    CHECK(clamped.clamped() == 1);
    CHECK(clamped.renormalised() >= 1);
}

TEST_CASE("normal-map readers: bounded mutation fuzz of the PNG and EXR readers") {
    // Seeds: the committed corpus (tests/data/fuzz) and files written here.
    std::vector<std::pair<std::string, std::vector<std::uint8_t>>> seeds;
    for (const char* name : {"rgb8.png", "rgba16.png", "gray8.png", "palette.png", "normal_float.exr", "normal_half_zip.exr"})
        seeds.emplace_back(name, read_bytes(std::string(GLINT_TEST_DATA_DIR) + "/fuzz/" + name));
    for (const auto& s : seeds) REQUIRE_MESSAGE(s.second.size() > 8, s.first);
    const auto start = std::chrono::steady_clock::now();
    std::size_t runs = 0, accepted = 0, rejected = 0;
    std::uint32_t counter = 0;
    const auto rnd = [&counter](std::uint32_t n) { return glint::pcg3d(glm::uvec3(counter++, 0xf022u, 3u)).x % n; };
    for (const auto& seed : seeds) {
        const bool exr = seed.first.size() > 4 && seed.first.substr(seed.first.size() - 4) == ".exr";
        const int mutations = exr ? 2000 : 10000;
        for (int i = 0; i < mutations; ++i) {
            std::vector<std::uint8_t> b = seed.second;
            const int edits = 1 + static_cast<int>(rnd(4));
            for (int e = 0; e < edits && !b.empty(); ++e) {
                const std::uint32_t kind = rnd(5), at = rnd(static_cast<std::uint32_t>(b.size()));
                if (kind == 0) b[at] ^= static_cast<std::uint8_t>(1u << rnd(8));                      // flip a bit
                else if (kind == 1) b[at] = static_cast<std::uint8_t>(rnd(256));                       // set a byte
                else if (kind == 2) b.resize(at);                                                      // truncate
                else if (kind == 3) b.insert(b.begin() + at, static_cast<std::uint8_t>(rnd(256)));      // insert
                else for (std::uint32_t k = at; k < std::min<std::size_t>(b.size(), at + 4); ++k) b[k] = 0xff;  // a large length
            }
            ++runs;
            try {
                if (exr) {
                    write_bytes(tmp + "/fuzz.exr", b);
                    (void)glint::io::read_normal_map(tmp + "/fuzz.exr");
                } else {
                    // Half the runs ignore the checksums, so that mutations reach the decoder.
                    const auto img = glint::io::read_png_memory(b.data(), b.size(), "fuzz", (i & 1) == 0);
                    CHECK(img.values.size() == static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height) * static_cast<std::size_t>(img.channels));
                }
                ++accepted;
            } catch (const glint::error&) {
                ++rejected;
            }
        }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    MESSAGE("fuzz: " << runs << " mutated inputs (" << accepted << " decoded, " << rejected << " rejected with glint::error) in " << seconds << " s");
    CHECK(runs == accepted + rejected);
    CHECK(rejected > runs / 4);
}
