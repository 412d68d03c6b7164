// Hides a value from the optimiser (it may have changed), without a memory round trip: the scalar kernel loops call
// it once per μ so that the compiler cannot vectorise or hoist them.
#pragma once

namespace metalfit::bench {

inline void opaque(float& v) {
#if defined(__x86_64__) || defined(__i386__)
    asm volatile("" : "+x"(v));
#elif defined(__aarch64__)
    asm volatile("" : "+w"(v));
#else
    asm volatile("" : "+m"(v) : : "memory");
#endif
}

}  // namespace metalfit::bench
