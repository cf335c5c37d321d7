#pragma once
// GLSL's transcendental functions on float, computed by tessref's own code instead of the C
// library's, so that the shader executor gives the same bits on every x86-64 machine and with any
// compiler that keeps IEEE semantics (no FMA contraction, no fast-math, SSE arithmetic, the default
// rounding mode and no flush-to-zero). docs/glsl-precision.md has the summary.
//
// Special values follow C99 Annex F (the C library's sinf, powf, ...). Where GLSL leaves a result
// undefined, that convention decides it, as noted per function. Every NaN result is the quiet NaN
// 0x7fc00000, whatever NaN came in.
//
// Accuracy: "max" is the largest error measured by tests/shader/glsl_math_test.cpp against libm's
// double functions, in ULPs of the float result. "max 0.5 ULP" means correctly rounded but for rare
// exact values within ~2^-45 (relative) of halfway between two floats, which may round to either
// (error at most 0.5000001 ULP; one float in 600 million for asinh and acosh). "GLSL" is GLSL 4.60
// section 4.7.1's requirement; "undefined" there means no requirement at all. (Vulkan's SPIR-V
// environment asks sin and cos for an absolute error of at most 2^-11 on [-pi, pi].)
namespace tessref::shader::math {

// Trigonometric. GLSL: precision undefined. Measured: max 0.5 ULP on |x| <= 1e5 and in every
// binade up to FLT_MAX (the argument reduction keeps full accuracy for any float).
// sin(+-0) = +-0, tan(+-0) = +-0, cos(+-0) = 1; all three give NaN at +-inf.
float sin(float x);
float cos(float x);
float tan(float x);

// Inverse trigonometric. GLSL: precision undefined. Measured: max 0.5 ULP (asin, acos on [-1, 1];
// atan over all floats; atan2 over all pairs of finite floats).
// asin, acos: GLSL leaves |x| > 1 undefined; NaN here. asin(+-0) = +-0, acos(1) = +0.
float asin(float x);
float acos(float x);
// GLSL atan(y_over_x). atan(+-0) = +-0, atan(+-inf) = +-pi/2.
float atan(float x);
// GLSL atan(y, x), C's atan2. GLSL leaves x = y = 0 undefined; C99's quadrants here:
// atan2(+-0, +0) = +-0, atan2(+-0, -0) = +-pi, atan2(+-inf, +inf) = +-pi/4,
// atan2(+-inf, -inf) = +-3pi/4.
float atan2(float y, float x);

// Hyperbolic. GLSL: sinh, cosh and tanh inherit the error of their formulas in e^x; the inverse
// ones' precision is undefined. Measured: max 0.5 ULP (sinh, cosh on [-90, 90], beyond which they
// overflow; tanh, asinh over all floats; acosh on [1, FLT_MAX]; atanh on (-1, 1)).
// sinh(+-0) = +-0, sinh(+-inf) = +-inf; cosh(+-0) = 1, cosh(+-inf) = +inf;
// tanh(+-0) = +-0, tanh(+-inf) = +-1; asinh(+-0) = +-0, asinh(+-inf) = +-inf.
float sinh(float x);
float cosh(float x);
float tanh(float x);
float asinh(float x);
// GLSL leaves x < 1 undefined; NaN here. acosh(1) = +0, acosh(+inf) = +inf.
float acosh(float x);
// GLSL leaves |x| >= 1 undefined; +-inf at +-1 (C's pole), NaN beyond. atanh(+-0) = +-0.
float atanh(float x);

// GLSL: (3 + 2|x|) ULP. Measured: max 0.5 ULP; exp2 is exact at integers.
// exp(+-0) = 1, exp(-inf) = +0, exp(+inf) = +inf; the same for exp2.
float exp(float x);
float exp2(float x);

// GLSL: 3 ULP outside [0.5, 2], absolute error below 2^-21 inside. Measured: max 0.5 ULP over all
// positive floats, denormals included; log2 is exact at powers of 2.
// GLSL leaves x <= 0 undefined; C's values here: log(+-0) = -inf, log(x < 0) = NaN.
// log(1) = +0, log(+inf) = +inf; the same for log2.
float log(float x);
float log2(float x);

// GLSL: the error of exp2(y * log2(x)). Measured: max 0.5 ULP, but a result exactly halfway
// between two floats (such as some x^2) may round to either.
// GLSL leaves x < 0, and x = 0 with y <= 0, undefined; C's powf here: pow(x, +-0) = 1 and
// pow(1, y) = 1 for any x, y (even NaN); pow(x < 0, y) = +-|x|^y for integer y, NaN otherwise;
// pow(+-0, y < 0) = +inf (-inf for -0 and odd y); pow(+-0, y > 0) = +0 (-0 for -0 and odd y);
// and C's rules for infinite x or y.
float pow(float x, float y);

// The same functions over arrays: out[i] = f(x[i]) for 0 <= i < n, bit for bit as the scalar
// ones. out may be x (or y).
void sin_n(const float* x, float* out, int n);
void cos_n(const float* x, float* out, int n);
void tan_n(const float* x, float* out, int n);
void asin_n(const float* x, float* out, int n);
void acos_n(const float* x, float* out, int n);
void atan_n(const float* x, float* out, int n);
void sinh_n(const float* x, float* out, int n);
void cosh_n(const float* x, float* out, int n);
void tanh_n(const float* x, float* out, int n);
void asinh_n(const float* x, float* out, int n);
void acosh_n(const float* x, float* out, int n);
void atanh_n(const float* x, float* out, int n);
void exp_n(const float* x, float* out, int n);
void exp2_n(const float* x, float* out, int n);
void log_n(const float* x, float* out, int n);
void log2_n(const float* x, float* out, int n);
// out[i] = pow(x[i], y[i]).
void pow_n(const float* x, const float* y, float* out, int n);
// out[i] = atan2(y[i], x[i]) (GLSL atan(y, x)).
void atan2_n(const float* y, const float* x, float* out, int n);

}  // namespace tessref::shader::math
