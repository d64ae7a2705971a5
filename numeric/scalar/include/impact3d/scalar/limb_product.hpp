// The exact product of two 6-limb integers (FixedFloat<334>'s significands) in mulx/adcx/adox
// assembly, fully unrolled: 36 limb products summed in two carry chains at once, adcx carrying the low
// halves and adox the high ones, as Intel lays out in "New Instructions Supporting Large Integer
// Arithmetic on Intel Architecture Processors" (2012). On this project's machine Debian's GMP 6.2.1
// takes its generic mul/adc loops (its code for this processor uses neither instruction): 18 ns a
// product there against 12 ns here (BENCHMARKS.md), and a 100-digit collision makes about 480 of them.
// Most are rounded from the product's top alone (multiply6_high: 21 of the 36 limb products, with a
// bound on the rest), the whole product taken only where that top leaves the rounding undecided.
//
// x86-64 only, and only where the processor has BMI2 (mulx) and ADX (adcx, adox), read once from cpuid;
// elsewhere, under tools that hide them (valgrind does), and with IMPACT3D_GMP_PRODUCT set, FixedFloat
// keeps GMP's mpn_mul_n. The two give the same integer, which tests/mechanics/check_fixed_float.cpp holds limb for
// limb.
#pragma once

#include <cstdint>
#include <cstdlib>

#if defined(__x86_64__) && defined(__GNUC__)
#include <cpuid.h>
#define IMPACT3D_LIMB_PRODUCT_ASM 1
#else
#define IMPACT3D_LIMB_PRODUCT_ASM 0
#endif

namespace impact3d::mp::limb_product {

using Limb = std::uint64_t;

#if IMPACT3D_LIMB_PRODUCT_ASM

// cpuid leaf 7: EBX bit 8 is BMI2, bit 19 ADX (Intel SDM vol. 2A, CPUID). Read at start-up; a product
// taken before then (another translation unit's static initialiser) reads false and takes GMP's path,
// which gives the same integer. IMPACT3D_GMP_PRODUCT set (to anything but empty) takes GMP's path
// everywhere: the tests run once so, to hold that path too on processors that have the instructions.
inline bool has_mulx_adx() {
  if (const char* v = std::getenv("IMPACT3D_GMP_PRODUCT"); v != nullptr && *v != '\0') return false;
  unsigned a = 0, b = 0, c = 0, d = 0;
  if (__get_cpuid_count(7, 0, &a, &b, &c, &d) == 0) return false;
  return (b & (1u << 8)) != 0 && (b & (1u << 19)) != 0;
}
inline const bool kAvailable = has_mulx_adx();

// b's limbs are addressed from one register (the "m" operand tells the compiler they are read): six
// memory operands could each take a register of their own in an unoptimised or sanitised build, more
// than x86-64 has left beside the twelve a row holds.
//
// One row: limbs s0..s5 plus rdx * b[0..5] into s0..s6. The xor clears both carry flags; adcx adds the
// low halves along CF, adox the high halves along OF, so the two chains interleave without waiting on
// each other. The top limb s6 takes the last high half and both chains' final carries; the sum fits in
// seven limbs (s < 2^384 and rdx * b < 2^448 - 2^384), so no carry leaves it. A shorter row (the top
// product's, below) is the same with fewer of b's limbs: IMPACT3D_LIMB_STEP adds one limb product into
// two accumulators, IMPACT3D_LIMB_LAST the row's last into its top limb.
#define IMPACT3D_LIMB_STEP(offset, q, next) \
  "mulx " #offset "(%[b]), %[lo], %[hi]\n\t" "adcx %[lo], %[" #q "]\n\t" "adox %[hi], %[" #next "]\n\t"
#define IMPACT3D_LIMB_LAST(offset, q, top)                                                              \
  "mulx " #offset "(%[b]), %[lo], %[" #top "]\n\t" "adcx %[lo], %[" #q "]\n\t" "adox %[z], %[" #top "]\n\t" \
  "adcx %[z], %[" #top "]"
#define IMPACT3D_LIMB_ROW_INPUTS(n) "d"(ai), [b] "r"(b), "m"(*reinterpret_cast<const Limb(*)[n]>(b))
#define IMPACT3D_PRODUCT_ROW(s0, s1, s2, s3, s4, s5, s6)                                                      \
  asm("xor %k[z], %k[z]\n\t"                                                                                  \
      IMPACT3D_LIMB_STEP(0, q0, q1) IMPACT3D_LIMB_STEP(8, q1, q2) IMPACT3D_LIMB_STEP(16, q2, q3)               \
      IMPACT3D_LIMB_STEP(24, q3, q4) IMPACT3D_LIMB_STEP(32, q4, q5) IMPACT3D_LIMB_LAST(40, q5, q6)             \
      : [q0] "+r"(s0), [q1] "+r"(s1), [q2] "+r"(s2), [q3] "+r"(s3), [q4] "+r"(s4), [q5] "+r"(s5),             \
        [q6] "=&r"(s6), [lo] "=&r"(lo), [hi] "=&r"(hi), [z] "=&r"(z)                                          \
      : IMPACT3D_LIMB_ROW_INPUTS(6)                                                                           \
      : "cc")

// w = a * b, all 12 limbs, least significant first (GMP's order). Call only where kAvailable.
[[gnu::always_inline]] inline void multiply6(Limb (&w)[12], const Limb* a, const Limb* b) {
  Limb r0, r1, r2, r3, r4, r5, r6, r7, r8, r9, r10, r11, lo, hi, z;
  Limb ai = a[0];
  // The first row has nothing to add to: one carry chain.
  asm("mulx 0(%[b]), %[r0], %[r1]\n\t"
      "mulx 8(%[b]), %[lo], %[r2]\n\t" "add %[lo], %[r1]\n\t"
      "mulx 16(%[b]), %[lo], %[r3]\n\t" "adc %[lo], %[r2]\n\t"
      "mulx 24(%[b]), %[lo], %[r4]\n\t" "adc %[lo], %[r3]\n\t"
      "mulx 32(%[b]), %[lo], %[r5]\n\t" "adc %[lo], %[r4]\n\t"
      "mulx 40(%[b]), %[lo], %[r6]\n\t" "adc %[lo], %[r5]\n\t" "adc $0, %[r6]"
      : [r0] "=&r"(r0), [r1] "=&r"(r1), [r2] "=&r"(r2), [r3] "=&r"(r3), [r4] "=&r"(r4), [r5] "=&r"(r5),
        [r6] "=&r"(r6), [lo] "=&r"(lo)
      : "d"(ai), [b] "r"(b), "m"(*reinterpret_cast<const Limb(*)[6]>(b))
      : "cc");
  ai = a[1];
  IMPACT3D_PRODUCT_ROW(r1, r2, r3, r4, r5, r6, r7);
  ai = a[2];
  IMPACT3D_PRODUCT_ROW(r2, r3, r4, r5, r6, r7, r8);
  ai = a[3];
  IMPACT3D_PRODUCT_ROW(r3, r4, r5, r6, r7, r8, r9);
  ai = a[4];
  IMPACT3D_PRODUCT_ROW(r4, r5, r6, r7, r8, r9, r10);
  ai = a[5];
  IMPACT3D_PRODUCT_ROW(r5, r6, r7, r8, r9, r10, r11);
  w[0] = r0, w[1] = r1, w[2] = r2, w[3] = r3, w[4] = r4, w[5] = r5;
  w[6] = r6, w[7] = r7, w[8] = r8, w[9] = r9, w[10] = r10, w[11] = r11;
}

// The top of a * b, for a product rounded to 334 bits (FixedFloat's top_decides): w = limbs 5 .. 11 of
// T, the sum of the 21 limb products a_i b_j with i + j >= 5, 15 fewer than the whole. Row i takes
// b's top i + 1 limbs. The 15 left out (i + j <= 4) sum to at most sum over c = 0..4 of (c + 1)(B - 1)^2
// B^c, B = 2^64, less than 5 B^6: so a * b lies in [T, T + 5 * 2^384). Each row's sum fits in its limbs
// as the whole product's rows do (the partial sum before row i is below B^(i + 1) times 2^320).
[[gnu::always_inline]] inline void multiply6_high(Limb (&w)[7], const Limb* a, const Limb* b_all) {
  Limb r5, r6, r7, r8, r9, r10, r11, lo, hi, z;
  Limb ai = a[0];
  const Limb* b = b_all + 5;
  asm("mulx (%[b]), %[r5], %[r6]" : [r5] "=&r"(r5), [r6] "=&r"(r6) : IMPACT3D_LIMB_ROW_INPUTS(1));
  ai = a[1], b = b_all + 4;
  asm("xor %k[z], %k[z]\n\t" IMPACT3D_LIMB_STEP(0, q0, q1) IMPACT3D_LIMB_LAST(8, q1, q2)
      : [q0] "+r"(r5), [q1] "+r"(r6), [q2] "=&r"(r7), [lo] "=&r"(lo), [hi] "=&r"(hi), [z] "=&r"(z)
      : IMPACT3D_LIMB_ROW_INPUTS(2)
      : "cc");
  ai = a[2], b = b_all + 3;
  asm("xor %k[z], %k[z]\n\t" IMPACT3D_LIMB_STEP(0, q0, q1) IMPACT3D_LIMB_STEP(8, q1, q2) IMPACT3D_LIMB_LAST(16, q2, q3)
      : [q0] "+r"(r5), [q1] "+r"(r6), [q2] "+r"(r7), [q3] "=&r"(r8), [lo] "=&r"(lo), [hi] "=&r"(hi), [z] "=&r"(z)
      : IMPACT3D_LIMB_ROW_INPUTS(3)
      : "cc");
  ai = a[3], b = b_all + 2;
  asm("xor %k[z], %k[z]\n\t" IMPACT3D_LIMB_STEP(0, q0, q1) IMPACT3D_LIMB_STEP(8, q1, q2) IMPACT3D_LIMB_STEP(16, q2, q3)
          IMPACT3D_LIMB_LAST(24, q3, q4)
      : [q0] "+r"(r5), [q1] "+r"(r6), [q2] "+r"(r7), [q3] "+r"(r8), [q4] "=&r"(r9), [lo] "=&r"(lo), [hi] "=&r"(hi),
        [z] "=&r"(z)
      : IMPACT3D_LIMB_ROW_INPUTS(4)
      : "cc");
  ai = a[4], b = b_all + 1;
  asm("xor %k[z], %k[z]\n\t" IMPACT3D_LIMB_STEP(0, q0, q1) IMPACT3D_LIMB_STEP(8, q1, q2) IMPACT3D_LIMB_STEP(16, q2, q3)
          IMPACT3D_LIMB_STEP(24, q3, q4) IMPACT3D_LIMB_LAST(32, q4, q5)
      : [q0] "+r"(r5), [q1] "+r"(r6), [q2] "+r"(r7), [q3] "+r"(r8), [q4] "+r"(r9), [q5] "=&r"(r10), [lo] "=&r"(lo),
        [hi] "=&r"(hi), [z] "=&r"(z)
      : IMPACT3D_LIMB_ROW_INPUTS(5)
      : "cc");
  ai = a[5], b = b_all;
  IMPACT3D_PRODUCT_ROW(r5, r6, r7, r8, r9, r10, r11);
  w[0] = r5, w[1] = r6, w[2] = r7, w[3] = r8, w[4] = r9, w[5] = r10, w[6] = r11;
}
#undef IMPACT3D_PRODUCT_ROW
#undef IMPACT3D_LIMB_ROW_INPUTS
#undef IMPACT3D_LIMB_LAST
#undef IMPACT3D_LIMB_STEP

#else

inline constexpr bool kAvailable = false;
inline void multiply6(Limb (&)[12], const Limb*, const Limb*) {}
inline void multiply6_high(Limb (&)[7], const Limb*, const Limb*) {}

#endif

}  // namespace impact3d::mp::limb_product
