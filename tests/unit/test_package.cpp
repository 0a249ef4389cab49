// The package itself: version, embedded kernel texts.
#include <doctest/doctest.h>

#include <fstream>
#include <sstream>
#include <string>

#include <glint/glint.hpp>
#include <glint/glsl.hpp>

TEST_CASE("the version header agrees with the CMake project version") {
    CHECK(std::string(GLINT_VERSION_STRING) == GLINT_PROJECT_VERSION);
}

TEST_CASE("glsl_source returns each kernel file's text, prelude first") {
    auto names = glint::glsl_kernel_names();
    REQUIRE(!names.empty());
    CHECK(names.front() == "prelude.glsl");
    for (auto name : names) {
        CAPTURE(name);
        std::ifstream file(std::string(GLINT_KERNEL_DIR) + "/" + std::string(name));
        REQUIRE(file.good());
        std::stringstream text;
        text << file.rdbuf();
        CHECK(glint::glsl_source(name) == text.str());
    }
}

TEST_CASE("glsl_source rejects an unknown name, naming it") {
    try {
        (void)glint::glsl_source("nonexistent.glsl");
        FAIL("no exception");
    } catch (const glint::error& e) {
        CHECK(std::string(e.what()).find("nonexistent.glsl") != std::string::npos);
    }
}
