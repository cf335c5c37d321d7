// GLSL.std.450 on the executor. Transcendental functions come from glsl_math.h (tessref's own, the
// same bits on every machine); the rest are exact IEEE operations written in the order the GLSL
// specification (and glm, which the built-in programs use) gives them.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

#include <spirv/unified1/GLSL.std.450.h>

#include "common/half_float.h"
#include "shader/executor_runner.h"
#include "shader/glsl_math.h"

namespace tessref::shader {
namespace {

template <class T>
T fsign(T a) {
  return a > T(0) ? T(1) : a < T(0) ? T(-1) : a;  // keeps ±0 and NaN
}

std::uint32_t find_lsb(std::uint32_t v) { return v ? std::uint32_t(std::countr_zero(v)) : 0xffffffffu; }
std::uint32_t find_umsb(std::uint32_t v) { return v ? 31u - std::uint32_t(std::countl_zero(v)) : 0xffffffffu; }
std::uint32_t find_smsb(std::uint32_t v) { return find_umsb(std::int32_t(v) < 0 ? ~v : v); }

}  // namespace

void Runner::ext(const XIns& x) {
  auto f1 = [&](auto f) {
    if (x.s == Scalar::F64) map1<double, double>(x, [&](double a) { return f(a); });
    else map1<float, float>(x, [&](float a) { return f(a); });
  };
  auto f2 = [&](auto f) {
    if (x.s == Scalar::F64) map2<double, double>(x, [&](double a, double b) { return f(a, b); });
    else map2<float, float>(x, [&](float a, float b) { return f(a, b); });
  };
  auto f3 = [&](auto f) {
    if (x.s == Scalar::F64) map3<double, double>(x, [&](double a, double b, double c) { return f(a, b, c); });
    else map3<float, float>(x, [&](float a, float b, float c) { return f(a, b, c); });
  };
  auto float_only = [&](float (*f)(float)) {
    if (x.s == Scalar::F64) fail("GLSL.std.450 transcendental function on doubles", 0, x.line);
    map1<float, float>(x, f);
  };

  const int op = int(x.aux);
  switch (op) {
    case GLSLstd450Round: f1([](auto a) { return std::round(a); }); break;
    case GLSLstd450RoundEven: f1([](auto a) { return std::nearbyint(a); }); break;
    case GLSLstd450Trunc: f1([](auto a) { return std::trunc(a); }); break;
    case GLSLstd450FAbs: f1([](auto a) { return std::fabs(a); }); break;
    case GLSLstd450SAbs: map1<std::uint32_t, std::uint32_t>(x, [](std::uint32_t a) { return std::int32_t(a) < 0 ? 0u - a : a; }); break;
    case GLSLstd450FSign: f1([](auto a) { return fsign(a); }); break;
    case GLSLstd450SSign: map1<std::int32_t, std::int32_t>(x, [](std::int32_t a) { return (a > 0) - (a < 0); }); break;
    case GLSLstd450Floor: f1([](auto a) { return std::floor(a); }); break;
    case GLSLstd450Ceil: f1([](auto a) { return std::ceil(a); }); break;
    case GLSLstd450Fract: f1([](auto a) { return a - std::floor(a); }); break;
    case GLSLstd450Radians: map1<float, float>(x, [](float a) { return a * 0.017453292519943295f; }); break;
    case GLSLstd450Degrees: map1<float, float>(x, [](float a) { return a * 57.29577951308232f; }); break;
    case GLSLstd450Sin: float_only(math::sin); break;
    case GLSLstd450Cos: float_only(math::cos); break;
    case GLSLstd450Tan: float_only(math::tan); break;
    case GLSLstd450Asin: float_only(math::asin); break;
    case GLSLstd450Acos: float_only(math::acos); break;
    case GLSLstd450Atan: float_only(math::atan); break;
    case GLSLstd450Sinh: float_only(math::sinh); break;
    case GLSLstd450Cosh: float_only(math::cosh); break;
    case GLSLstd450Tanh: float_only(math::tanh); break;
    case GLSLstd450Asinh: float_only(math::asinh); break;
    case GLSLstd450Acosh: float_only(math::acosh); break;
    case GLSLstd450Atanh: float_only(math::atanh); break;
    case GLSLstd450Exp: float_only(math::exp); break;
    case GLSLstd450Log: float_only(math::log); break;
    case GLSLstd450Exp2: float_only(math::exp2); break;
    case GLSLstd450Log2: float_only(math::log2); break;
    case GLSLstd450Atan2: map2<float, float>(x, [](float y, float xx) { return math::atan2(y, xx); }); break;
    case GLSLstd450Pow: map2<float, float>(x, [](float a, float b) { return math::pow(a, b); }); break;
    case GLSLstd450Sqrt: f1([](auto a) { return std::sqrt(a); }); break;
    case GLSLstd450InverseSqrt: f1([](auto a) { return decltype(a)(1) / std::sqrt(a); }); break;
    case GLSLstd450FMin: case GLSLstd450NMin:
      f2([&](auto a, auto b) {
        if (op == GLSLstd450NMin && std::isnan(a)) return b;
        if (op == GLSLstd450NMin && std::isnan(b)) return a;
        return b < a ? b : a;
      });
      break;
    case GLSLstd450FMax: case GLSLstd450NMax:
      f2([&](auto a, auto b) {
        if (op == GLSLstd450NMax && std::isnan(a)) return b;
        if (op == GLSLstd450NMax && std::isnan(b)) return a;
        return a < b ? b : a;
      });
      break;
    case GLSLstd450UMin: map2<std::uint32_t, std::uint32_t>(x, [](std::uint32_t a, std::uint32_t b) { return std::min(a, b); }); break;
    case GLSLstd450SMin: map2<std::int32_t, std::int32_t>(x, [](std::int32_t a, std::int32_t b) { return std::min(a, b); }); break;
    case GLSLstd450UMax: map2<std::uint32_t, std::uint32_t>(x, [](std::uint32_t a, std::uint32_t b) { return std::max(a, b); }); break;
    case GLSLstd450SMax: map2<std::int32_t, std::int32_t>(x, [](std::int32_t a, std::int32_t b) { return std::max(a, b); }); break;
    case GLSLstd450FClamp: case GLSLstd450NClamp:
      f3([](auto v, auto lo, auto hi) {
        auto t = v < lo ? lo : v;  // max(v, lo)
        return hi < t ? hi : t;    // min(., hi)
      });
      break;
    case GLSLstd450UClamp:
      map3<std::uint32_t, std::uint32_t>(x, [](std::uint32_t v, std::uint32_t lo, std::uint32_t hi) { return std::min(std::max(v, lo), hi); });
      break;
    case GLSLstd450SClamp:
      map3<std::int32_t, std::int32_t>(x, [](std::int32_t v, std::int32_t lo, std::int32_t hi) { return std::min(std::max(v, lo), hi); });
      break;
    case GLSLstd450FMix: f3([](auto a, auto b, auto t) { return a * (decltype(a)(1) - t) + b * t; }); break;
    case GLSLstd450Step: f2([](auto edge, auto v) { return v < edge ? decltype(v)(0) : decltype(v)(1); }); break;
    case GLSLstd450SmoothStep:
      f3([](auto e0, auto e1, auto v) {
        using T = decltype(v);
        T t = (v - e0) / (e1 - e0);
        t = t < T(0) ? T(0) : (T(1) < t ? T(1) : t);
        return t * t * (T(3) - T(2) * t);
      });
      break;
    case GLSLstd450Fma: f3([](auto a, auto b, auto c) { return std::fma(a, b, c); }); break;
    case GLSLstd450Ldexp: {
      for (std::uint32_t c = 0; c < x.n; ++c) {
        const std::int32_t* e = row<std::int32_t>(x.b, c);
        if (x.s == Scalar::F64) {
          const double* a = row<double>(x.a, c);
          put(row<double>(x.dst, c), [&](int l) { return std::ldexp(a[l], std::clamp(e[l], -2000, 2000)); });
        } else {
          const float* a = row<float>(x.a, c);
          put(row<float>(x.dst, c), [&](int l) { return std::ldexp(a[l], std::clamp(e[l], -400, 400)); });
        }
      }
      break;
    }
    case GLSLstd450Modf: case GLSLstd450Frexp: case GLSLstd450ModfStruct: case GLSLstd450FrexpStruct: {
      // The fraction (mantissa) goes to dst, the whole part (exponent) to the rows at x.c: the
      // result struct's second member, or staging rows stored through the pointer operand x.b.
      const bool modf = op == GLSLstd450Modf || op == GLSLstd450ModfStruct;
      for (std::uint32_t c = 0; c < x.n; ++c) {
        auto go = [&](auto zero) {
          using T = decltype(zero);
          const T* a = row<T>(x.a, c);
          if (modf) {
            T* whole = row<T>(x.c, c);
            put(whole, [&](int l) { return std::trunc(a[l]); });
            // Both parts have x's sign: -1.0 gives -0.0 and -1.0; +-inf gives +-0.0.
            put(row<T>(x.dst, c), [&](int l) {
              return std::isinf(a[l]) ? std::copysign(T(0), a[l]) : std::copysign(a[l] - whole[l], a[l]);
            });
          } else {
            std::int32_t* exponent = row<std::int32_t>(x.c, c);
            put(exponent, [&](int l) {
              int e = 0;
              std::frexp(a[l], &e);
              return std::int32_t(e);
            });
            put(row<T>(x.dst, c), [&](int l) {
              int e = 0;
              return std::frexp(a[l], &e);
            });
          }
        };
        if (x.s == Scalar::F64) go(double{});
        else go(float{});
      }
      if (x.b != kNone) {
        XIns st;
        st.aux = x.b;
        st.a = x.c;
        store(st);
      }
      break;
    }
    case GLSLstd450FindILsb: map1<std::uint32_t, std::uint32_t>(x, find_lsb); break;
    case GLSLstd450FindSMsb: map1<std::uint32_t, std::uint32_t>(x, find_smsb); break;
    case GLSLstd450FindUMsb: map1<std::uint32_t, std::uint32_t>(x, find_umsb); break;
    case GLSLstd450Length: case GLSLstd450Distance: {
      auto go = [&](auto zero) {
        using T = decltype(zero);
        const bool dist = op == GLSLstd450Distance;
        put(row<T>(x.dst), [&](int l) {
          T s = 0;
          for (std::uint32_t c = 0; c < x.m; ++c) {
            const T v = dist ? row<T>(x.a, c)[l] - row<T>(x.b, c)[l] : row<T>(x.a, c)[l];
            s = c == 0 ? v * v : s + v * v;
          }
          return std::sqrt(s);
        });
      };
      if (x.s == Scalar::F64) go(double{});
      else go(float{});
      break;
    }
    case GLSLstd450Normalize: {
      // glm's order: v * inversesqrt(dot(v, v)), inversesqrt = 1 / sqrt.
      auto go = [&](auto zero) {
        using T = decltype(zero);
        T inv_len[L];
        for (int l = 0; l < n; ++l) {
          T s = 0;
          for (std::uint32_t c = 0; c < x.m; ++c) {
            const T v = row<T>(x.a, c)[l];
            s = c == 0 ? v * v : s + v * v;
          }
          inv_len[l] = T(1) / std::sqrt(s);
        }
        for (std::uint32_t c = 0; c < x.n; ++c) {
          const T* a = row<T>(x.a, c);
          put(row<T>(x.dst, c), [&](int l) { return a[l] * inv_len[l]; });
        }
      };
      if (x.s == Scalar::F64) go(double{});
      else go(float{});
      break;
    }
    case GLSLstd450Cross: {
      auto go = [&](auto zero) {
        using T = decltype(zero);
        auto a = [&](int c) { return row<T>(x.a, c); };
        auto b = [&](int c) { return row<T>(x.b, c); };
        T out[3][L];
        for (int l = 0; l < n; ++l) {
          out[0][l] = a(1)[l] * b(2)[l] - b(1)[l] * a(2)[l];
          out[1][l] = a(2)[l] * b(0)[l] - b(2)[l] * a(0)[l];
          out[2][l] = a(0)[l] * b(1)[l] - b(0)[l] * a(1)[l];
        }
        for (int c = 0; c < 3; ++c) put(row<T>(x.dst, c), [&](int l) { return out[c][l]; });
      };
      if (x.s == Scalar::F64) go(double{});
      else go(float{});
      break;
    }
    case GLSLstd450FaceForward: case GLSLstd450Reflect: case GLSLstd450Refract: {
      auto go = [&](auto zero) {
        using T = decltype(zero);
        auto dot = [&](std::uint32_t ra, std::uint32_t rb, int l) {
          T s = 0;
          for (std::uint32_t c = 0; c < x.m; ++c) {
            const T v = row<T>(ra, c)[l] * row<T>(rb, c)[l];
            s = c == 0 ? v : s + v;
          }
          return s;
        };
        T k[L];
        for (int l = 0; l < n; ++l) {
          if (op == GLSLstd450FaceForward) k[l] = dot(x.c, x.b, l);  // dot(Nref, I)
          else k[l] = dot(x.b, x.a, l);                              // dot(N, I)
        }
        if (op == GLSLstd450FaceForward) {  // N: a, I: b, Nref: c
          for (std::uint32_t c = 0; c < x.n; ++c) {
            const T* nv = row<T>(x.a, c);
            put(row<T>(x.dst, c), [&](int l) { return k[l] < T(0) ? nv[l] : -nv[l]; });
          }
        } else if (op == GLSLstd450Reflect) {  // I - 2 * dot(N, I) * N (glm's order)
          for (std::uint32_t c = 0; c < x.n; ++c) {
            const T* iv = row<T>(x.a, c);
            const T* nv = row<T>(x.b, c);
            put(row<T>(x.dst, c), [&](int l) { return iv[l] - nv[l] * k[l] * T(2); });
          }
        } else {  // refract(I, N, eta)
          const T* eta = row<T>(x.c, 0);
          T kk[L];
          for (int l = 0; l < n; ++l) kk[l] = T(1) - eta[l] * eta[l] * (T(1) - k[l] * k[l]);
          for (std::uint32_t c = 0; c < x.n; ++c) {
            const T* iv = row<T>(x.a, c);
            const T* nv = row<T>(x.b, c);
            put(row<T>(x.dst, c), [&](int l) {
              if (kk[l] < T(0)) return T(0);
              return eta[l] * iv[l] - (eta[l] * k[l] + std::sqrt(kk[l])) * nv[l];
            });
          }
        }
      };
      if (x.s == Scalar::F64) go(double{});
      else go(float{});
      break;
    }
    case GLSLstd450Determinant: case GLSLstd450MatrixInverse: {
      // Cofactor expansion; the operand is square: x.m = its component count.
      const int dim = x.m == 4 ? 2 : x.m == 9 ? 3 : 4;
      auto go = [&](auto zero) {
        using T = decltype(zero);
        for (int l = 0; l < n; ++l) {
          if (!full && !mask[l]) continue;
          T a[4][4];
          for (int c = 0; c < dim; ++c)
            for (int r = 0; r < dim; ++r) a[c][r] = row<T>(x.a, std::uint32_t(c * dim + r))[l];
          auto det3 = [&](int c0, int c1, int c2, int r0, int r1, int r2) {
            return a[c0][r0] * (a[c1][r1] * a[c2][r2] - a[c2][r1] * a[c1][r2]) -
                   a[c1][r0] * (a[c0][r1] * a[c2][r2] - a[c2][r1] * a[c0][r2]) +
                   a[c2][r0] * (a[c0][r1] * a[c1][r2] - a[c1][r1] * a[c0][r2]);
          };
          T cof[4][4] = {};
          T det = 0;
          if (dim == 2) {
            cof[0][0] = a[1][1]; cof[0][1] = -a[1][0]; cof[1][0] = -a[0][1]; cof[1][1] = a[0][0];
            det = a[0][0] * a[1][1] - a[1][0] * a[0][1];
          } else {
            for (int c = 0; c < dim; ++c)
              for (int r = 0; r < dim; ++r) {
                int cs[3], rs[3], ci = 0, ri = 0;
                for (int k = 0; k < dim; ++k) {
                  if (k != c) cs[ci++] = k;
                  if (k != r) rs[ri++] = k;
                }
                T minor;
                if (dim == 3) minor = a[cs[0]][rs[0]] * a[cs[1]][rs[1]] - a[cs[1]][rs[0]] * a[cs[0]][rs[1]];
                else minor = det3(cs[0], cs[1], cs[2], rs[0], rs[1], rs[2]);
                cof[c][r] = ((c + r) & 1) ? -minor : minor;
              }
            for (int c = 0; c < dim; ++c) det = c == 0 ? a[0][0] * cof[0][0] : det + a[c][0] * cof[c][0];
          }
          if (op == GLSLstd450Determinant) {
            row<T>(x.dst)[l] = det;
          } else {  // inverse[c][r] = cofactor[r][c] / det
            for (int c = 0; c < dim; ++c)
              for (int r = 0; r < dim; ++r) row<T>(x.dst, std::uint32_t(c * dim + r))[l] = cof[r][c] / det;
          }
        }
      };
      if (x.s == Scalar::F64) go(double{});
      else go(float{});
      break;
    }
    case GLSLstd450PackHalf2x16:
      put(row<std::uint32_t>(x.dst), [&](int l) {
        return half_from_float(row<float>(x.a, 0)[l]) | (half_from_float(row<float>(x.a, 1)[l]) << 16);
      });
      break;
    case GLSLstd450UnpackHalf2x16:
      for (std::uint32_t c = 0; c < 2; ++c)
        put(row<float>(x.dst, c), [&](int l) { return half_to_float((row<std::uint32_t>(x.a)[l] >> (16 * c)) & 0xffffu); });
      break;
    case GLSLstd450PackUnorm4x8: case GLSLstd450PackSnorm4x8: case GLSLstd450PackUnorm2x16:
    case GLSLstd450PackSnorm2x16: {
      const bool snorm = op == GLSLstd450PackSnorm4x8 || op == GLSLstd450PackSnorm2x16;
      const bool bytes = op == GLSLstd450PackUnorm4x8 || op == GLSLstd450PackSnorm4x8;
      const int parts = bytes ? 4 : 2, bits = bytes ? 8 : 16;
      const float scale = snorm ? float((1 << (bits - 1)) - 1) : float((1 << bits) - 1);
      put(row<std::uint32_t>(x.dst), [&](int l) {
        std::uint32_t r = 0;
        for (int c = 0; c < parts; ++c) {
          float v = row<float>(x.a, std::uint32_t(c))[l];
          if (std::isnan(v)) v = 0.0f;  // GLSL leaves it undefined; 0, not a NaN conversion
          v = snorm ? std::clamp(v, -1.0f, 1.0f) : std::clamp(v, 0.0f, 1.0f);
          const std::int32_t q = std::int32_t(std::nearbyint(v * scale));
          r |= (std::uint32_t(q) & ((1u << bits) - 1u)) << (c * bits);
        }
        return r;
      });
      break;
    }
    case GLSLstd450UnpackUnorm4x8: case GLSLstd450UnpackSnorm4x8: case GLSLstd450UnpackUnorm2x16:
    case GLSLstd450UnpackSnorm2x16: {
      const bool snorm = op == GLSLstd450UnpackSnorm4x8 || op == GLSLstd450UnpackSnorm2x16;
      const bool bytes = op == GLSLstd450UnpackUnorm4x8 || op == GLSLstd450UnpackSnorm4x8;
      const int parts = bytes ? 4 : 2, bits = bytes ? 8 : 16;
      const float scale = snorm ? float((1 << (bits - 1)) - 1) : float((1 << bits) - 1);
      for (int c = 0; c < parts; ++c)
        put(row<float>(x.dst, std::uint32_t(c)), [&](int l) {
          const std::uint32_t raw = (row<std::uint32_t>(x.a)[l] >> (c * bits)) & ((1u << bits) - 1u);
          if (!snorm) return float(raw) / scale;
          const std::int32_t s = std::int32_t(raw << (32 - bits)) >> (32 - bits);
          return std::clamp(float(s) / scale, -1.0f, 1.0f);
        });
      break;
    }
    case GLSLstd450PackDouble2x32:
      put(row<double>(x.dst), [&](int l) {
        const std::uint64_t bits = std::uint64_t(row<std::uint32_t>(x.a, 0)[l]) |
                                   (std::uint64_t(row<std::uint32_t>(x.a, 1)[l]) << 32);
        return std::bit_cast<double>(bits);
      });
      break;
    case GLSLstd450UnpackDouble2x32:
      for (std::uint32_t c = 0; c < 2; ++c)
        put(row<std::uint32_t>(x.dst, c), [&](int l) {
          return std::uint32_t(std::bit_cast<std::uint64_t>(row<double>(x.a)[l]) >> (32 * c));
        });
      break;
    default:
      fail("GLSL.std.450 instruction " + std::to_string(op) + " is not supported", 0, x.line);
  }
}

}  // namespace tessref::shader
