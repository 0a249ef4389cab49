// launder(x): x, as a value the compiler must assume unknown, so that a timing loop cannot hoist
// work on it out of the loop (glint_report's loops and glint_frame_loop's draw-time).
#pragma once

#include <type_traits>

namespace glint_bench {

// Not benchmark::DoNotOptimize(x): its "+m,r" constraint makes g++ 12 read a float or double back
// as 0 when it picks the register form.
template <class T>
T launder(T x) {
    static_assert(std::is_floating_point<T>::value, "launder takes float or double");
    asm volatile("" : "+x"(x));  // x stays in an SSE register
    return x;
}

}  // namespace glint_bench
