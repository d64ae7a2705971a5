// The exact product of two 6-limb integers (FixedFloat<334>'s significands) in mulx/adcx/adox
// assembly, fully unrolled: 36 limb products summed in two carry chains at once, adcx carrying the low
// halves and adox the high ones, as Intel lays out in "New Instructions Supporting Large Integer
// Arithmetic on Intel Architecture Processors" (2012). On this project's machine Debian's GMP 6.2.1
// takes its generic mul/adc loops (its code for this processor uses neither instruction): 18 ns a
// product there against 12 ns here (BENCHMARKS.md), and a 100-digit collision makes about 480 of them.
//
// x86-64 only, and only where the processor has BMI2 (mulx) and ADX (adcx, adox), read once from cpuid;
// elsewhere, under tools that hide them (valgrind does), and with IMPACT3D_GMP_PRODUCT set, FixedFloat
// keeps GMP's mpn_mul_n. The two give the same integer, which tests/check_fixed_float.cpp holds limb for
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
// seven limbs (s < 2^384 and rdx * b < 2^448 - 2^384), so no carry leaves it.
#define IMPACT3D_PRODUCT_ROW(s0, s1, s2, s3, s4, s5, s6)                                                      \
  asm("xor %k[z], %k[z]\n\t"                                                                                  \
      "mulx 0(%[b]), %[lo], %[hi]\n\t" "adcx %[lo], %[q0]\n\t" "adox %[hi], %[q1]\n\t"                        \
      "mulx 8(%[b]), %[lo], %[hi]\n\t" "adcx %[lo], %[q1]\n\t" "adox %[hi], %[q2]\n\t"                        \
      "mulx 16(%[b]), %[lo], %[hi]\n\t" "adcx %[lo], %[q2]\n\t" "adox %[hi], %[q3]\n\t"                       \
      "mulx 24(%[b]), %[lo], %[hi]\n\t" "adcx %[lo], %[q3]\n\t" "adox %[hi], %[q4]\n\t"                       \
      "mulx 32(%[b]), %[lo], %[hi]\n\t" "adcx %[lo], %[q4]\n\t" "adox %[hi], %[q5]\n\t"                       \
      "mulx 40(%[b]), %[lo], %[q6]\n\t" "adcx %[lo], %[q5]\n\t" "adox %[z], %[q6]\n\t" "adcx %[z], %[q6]"     \
      : [q0] "+r"(s0), [q1] "+r"(s1), [q2] "+r"(s2), [q3] "+r"(s3), [q4] "+r"(s4), [q5] "+r"(s5),             \
        [q6] "=&r"(s6), [lo] "=&r"(lo), [hi] "=&r"(hi), [z] "=&r"(z)                                          \
      : "d"(ai), [b] "r"(b), "m"(*reinterpret_cast<const Limb(*)[6]>(b))                                      \
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
#undef IMPACT3D_PRODUCT_ROW

#else

inline constexpr bool kAvailable = false;
inline void multiply6(Limb (&)[12], const Limb*, const Limb*) {}

#endif

}  // namespace impact3d::mp::limb_product
