// Counts the allocations of a test binary while `counting` is set: replaces the global operator
// new and delete by malloc and free plus a counter. Include it in exactly one source file of a
// binary (it defines the replacements). GCC then sees free() on what it thinks came from new.
#pragma once
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

#include <atomic>
#include <cstdlib>
#include <new>

namespace glint_test {
inline std::atomic<bool> counting{false};
inline std::atomic<long> allocations{0};
}  // namespace glint_test

void* operator new(std::size_t n) {
    if (glint_test::counting) ++glint_test::allocations;
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
