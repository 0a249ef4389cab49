// The harness itself: a context on llvmpipe, and a shader that must fail to compile does.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "parity.hpp"

TEST_CASE("the context is OpenGL 4.5 on Mesa llvmpipe") {
    const std::string renderer = glint_test::gl().renderer();
    const std::string version = glint_test::gl().version();
    MESSAGE("GL_RENDERER: " << renderer << "; GL_VERSION: " << version);
    CHECK(renderer.find("llvmpipe") != std::string::npos);
    CHECK(version.rfind("4.5", 0) == 0);
}

TEST_CASE("the runner round-trips data and reports compile errors") {
    std::vector<std::uint32_t> in = {1u, 2u, 3u, 0xffffffffu};
    auto out = glint_test::map_words({}, "out0[i] = in0[i] * 3u + 1u;", in, in.size(), 1);
    REQUIRE(out.size() == 4u);
    CHECK(out[0] == 4u);
    CHECK(out[3] == 0xffffffffu * 3u + 1u);
    CHECK_THROWS_AS(glint_test::map_words({}, "out0[i] = undefined_function(i);", in, 1, 1), std::runtime_error);
}

TEST_CASE("a dispatch larger than one grid of groups reaches every item") {
    const std::size_t n = 64u * 65535u + 1000u;
    std::vector<std::uint32_t> none(1);
    auto out = glint_test::map_words({}, "out0[i] = i ^ 0x5a5a5a5au;", none, n, 1);
    std::size_t wrong = 0;
    for (std::size_t i = 0; i < n; ++i) wrong += out[i] != (static_cast<std::uint32_t>(i) ^ 0x5a5a5a5au);
    CHECK(wrong == 0u);
}

TEST_CASE("the comparison helpers count ulp distances and mismatches") {
    using glint_test::compare;
    const float one_up = std::nextafter(1.0f, 2.0f);
    auto s = compare(std::vector<float>{1.0f, one_up, -0.0f, 2.0f}, std::vector<float>{1.0f, 1.0f, 0.0f, 2.0f});
    CHECK(s.count == 4u);
    CHECK(s.differing == 1u);  // -0 and +0 are the same point
    CHECK(s.max == 1);
    CHECK(glint_test::ulp_distance(-std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::denorm_min()) == 2);
    auto w = compare(std::vector<std::uint32_t>{3u, 7u}, std::vector<std::uint32_t>{3u, 4u});
    CHECK(w.differing == 1u);
    CHECK(w.max == 3);
    CHECK(w.rate() == doctest::Approx(0.5));
}
