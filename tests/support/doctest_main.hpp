// The main() of every doctest binary: doctest's own, and a failure when a run selected no test
// case. CTest runs each case by name (doctest_discover_tests), and a name holding ';' reaches the
// binary cut at it (CMake's list separator), which selects nothing: doctest would then report
// success for a test that never ran. So test names must not hold ';', and this catches any that
// slips through.
#pragma once

#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <cstdio>

namespace glint_test {

inline int& test_cases_started() {
    static int n = 0;
    return n;
}

struct test_case_counter : doctest::IReporter {
    explicit test_case_counter(const doctest::ContextOptions&) {}
    void report_query(const doctest::QueryData&) override {}
    void test_run_start() override {}
    void test_run_end(const doctest::TestRunStats&) override {}
    void test_case_start(const doctest::TestCaseData&) override { ++test_cases_started(); }
    void test_case_reenter(const doctest::TestCaseData&) override {}
    void test_case_end(const doctest::CurrentTestCaseStats&) override {}
    void test_case_exception(const doctest::TestCaseException&) override {}
    void subcase_start(const doctest::SubcaseSignature&) override {}
    void subcase_end() override {}
    void log_assert(const doctest::AssertData&) override {}
    void log_message(const doctest::MessageData&) override {}
    void test_case_skipped(const doctest::TestCaseData&) override {}
};

}  // namespace glint_test

REGISTER_LISTENER("glint_test_case_counter", 1, glint_test::test_case_counter);

int main(int argc, char** argv) {
    doctest::Context context(argc, argv);
    const int result = context.run();
    if (context.shouldExit()) return result;  // --list-test-cases, --help, ...
    if (glint_test::test_cases_started() == 0) {
        std::fprintf(stderr, "glint tests: no test case was selected (a test name with ';' is cut there by CTest)\n");
        return result != 0 ? result : 1;
    }
    return result;
}
