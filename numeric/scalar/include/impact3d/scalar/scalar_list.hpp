// The scalar types impact3d is instantiated, dispatched and verified at: the one list, as macros alone
// (no type is needed to name them), so that a source compiled once per scalar (numeric/CMakeLists.txt's
// impact3d_per_scalar) can ask the preprocessor whether its index is on the list. scalars.hpp gives the
// list as types; X(type, precision name, unit roundoff u): see there.
#pragma once

#define IMPACT3D_NUMERIC_SCALARS(X)        \
  X(double, "double", 0x1p-52)             \
  X(long double, "long-double", 0x1p-63)

#if IMPACT3D_MULTIPRECISION
#define IMPACT3D_MULTIPRECISION_SCALARS(X)            \
  X(::impact3d::mp::float128, "float128", 0x1p-112)   \
  X(::impact3d::mp::float50, "50", 1e-49)             \
  X(::impact3d::mp::float100, "100", 1e-99)
#else
#define IMPACT3D_MULTIPRECISION_SCALARS(X)
#endif

#define IMPACT3D_SCALARS(X) IMPACT3D_NUMERIC_SCALARS(X) IMPACT3D_MULTIPRECISION_SCALARS(X)

#define IMPACT3D_SCALAR_COUNT_ONE_(type, name, u) +1
// The list's length, for #if.
#define IMPACT3D_SCALAR_COUNT (0 IMPACT3D_SCALARS(IMPACT3D_SCALAR_COUNT_ONE_))
