#include "stages/schemes/bezier_nets.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace tessref::schemes {

const char* to_string(Interpolant s) {
  switch (s) {
    case Interpolant::PN: return "pn";
    case Interpolant::Phong: return "phong";
    case Interpolant::NLSA: return "nlsa";
    case Interpolant::Nagata: return "nagata";
  }
  return "?";
}

// The per-edge rules spell out each operation in the order the GLSL twins (phong.tesc, nlsa.tesc,
// nagata.tesc) repeat it: at T = float the programs and their twins give the same bits.

template <class T>
Vec3<T> tangent_plane_projection(const Vec3<T>& q, const Vec3<T>& p, const Vec3<T>& n) {
  return q - glm::dot(q - p, n) * n;
}

template <class T>
Vec3<T> pn_tangent_point(const Vec3<T>& pi, const Vec3<T>& ni, const Vec3<T>& pj) {
  const T w = glm::dot(pj - pi, ni);
  return (T(2) * pi + pj - w * ni) / T(3);
}

template <class T>
Vec3<T> phong_edge_point(const Vec3<T>& p0, const Vec3<T>& n0, const Vec3<T>& p1,
                         const Vec3<T>& n1, T alpha) {
  const Vec3<T> mid = (p0 + p1) / T(2);
  const Vec3<T> projected =
      (tangent_plane_projection(p1, p0, n0) + tangent_plane_projection(p0, p1, n1)) / T(2);
  return mid + alpha * (projected - mid);
}

template <class T>
Vec3<T> nlsa_edge_point(const Vec3<T>& p0, const Vec3<T>& n0, const Vec3<T>& p1,
                        const Vec3<T>& n1) {
  const T l = glm::dot(n0, n1);
  // Swapping the ends turns t0 into -t1 and t1 into -t0 exactly: the result keeps its bits.
  const Vec3<T> t0 = n1 - l * n0;
  const Vec3<T> t1 = l * n1 - n0;
  const Vec3<T> d = p1 - p0;
  const Vec3<T> mid = (p0 + p1) / T(2);
  const T t00 = glm::dot(t0, t0), t11 = glm::dot(t1, t1);
  constexpr T kParallel = std::numeric_limits<T>::epsilon();
  if (!(t00 > kParallel) || !(t11 > kParallel)) return mid;
  // alpha beta t0 = d projected on t0; alpha-bar beta-bar t1 = d projected on t1 (Eq. 4, 5).
  return mid + ((glm::dot(d, t0) / t00) * t0 - (glm::dot(d, t1) / t11) * t1) / T(4);
}

template <class T>
Vec3<T> nagata_curvature(const Vec3<T>& p0, const Vec3<T>& n0, const Vec3<T>& p1,
                         const Vec3<T>& n1, T eps) {
  const Vec3<T> d = p1 - p0;
  const Vec3<T> nu = (n0 + n1) / T(2);
  const Vec3<T> dnu = (n0 - n1) / T(2);
  const T dv = glm::dot(d, nu);
  const T dd = glm::dot(d, dnu);
  const T dc = (T(1) - glm::dot(n0, n1)) / T(2);
  if (!(dc > eps) || !(T(1) - dc > eps)) return Vec3<T>(T(0));
  return (dd / (T(1) - dc)) * nu + (dv / dc) * dnu;
}

template <class T>
Vec3<T> nagata_edge_point(const Vec3<T>& p0, const Vec3<T>& n0, const Vec3<T>& p1,
                          const Vec3<T>& n1, T eps) {
  return (p0 + p1) / T(2) - nagata_curvature(p0, n0, p1, n1, eps) / T(2);
}

template <class T>
Vec3<T> quadratic_normal_mid(const Vec3<T>& p0, const Vec3<T>& n0, const Vec3<T>& p1,
                             const Vec3<T>& n1, bool corrected) {
  const Vec3<T> d = p1 - p0;
  const T dd = glm::dot(d, d);
  const Vec3<T> nsum = n0 + n1;
  const T k = corrected ? T(4) : T(2);
  // A zero-length edge has no plane to reflect across: keep the average direction.
  const T v = dd > T(0) ? k * glm::dot(d, nsum) / dd : T(0);
  return nsum - v * d;
}

template <class T>
QuadraticNet<T> quadratic_net(Interpolant s, const Vec3<T> p[3], const Vec3<T> n[3],
                              const InterpolantParams& params) {
  using Q = QuadraticNet<T>;
  auto edge = [&](int a, int b) -> Vec3<T> {
    switch (s) {
      case Interpolant::Phong: return phong_edge_point(p[a], n[a], p[b], n[b], T(params.phong_alpha));
      case Interpolant::NLSA: return nlsa_edge_point(p[a], n[a], p[b], n[b]);
      case Interpolant::Nagata: return nagata_edge_point(p[a], n[a], p[b], n[b], T(params.nagata_eps));
      case Interpolant::PN: break;
    }
    throw std::invalid_argument(std::string("quadratic_net: ") + to_string(s) + " is not a quadratic scheme");
  };
  Q q;
  q.b[Q::index(2, 0, 0)] = p[0];
  q.b[Q::index(0, 2, 0)] = p[1];
  q.b[Q::index(0, 0, 2)] = p[2];
  q.b[Q::index(1, 1, 0)] = edge(0, 1);
  q.b[Q::index(0, 1, 1)] = edge(1, 2);
  q.b[Q::index(1, 0, 1)] = edge(2, 0);
  return q;
}

template <class T>
CubicNet<T> elevate(const QuadraticNet<T>& q) {
  using Q = QuadraticNet<T>;
  using C = CubicNet<T>;
  C c;
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; i + j <= 3; ++j) {
      const int k = 3 - i - j;
      if (i == 3 || j == 3 || k == 3) {  // the corners, as they are (3 q / 3 may round)
        c.b[C::index(i, j, k)] = q.b[Q::index(i - i / 3, j - j / 3, k - k / 3)];
        continue;
      }
      Vec3<T> s(T(0));
      if (i > 0) s += T(i) * q.b[Q::index(i - 1, j, k)];
      if (j > 0) s += T(j) * q.b[Q::index(i, j - 1, k)];
      if (k > 0) s += T(k) * q.b[Q::index(i, j, k - 1)];
      c.b[C::index(i, j, k)] = s / T(3);
    }
  return c;
}

template <class T>
CubicNet<T> cubic_net(Interpolant s, const Vec3<T> p[3], const Vec3<T> n[3],
                      const InterpolantParams& params) {
  if (s != Interpolant::PN) return elevate(quadratic_net(s, p, n, params));
  using C = CubicNet<T>;
  C c;
  c.b[C::index(3, 0, 0)] = p[0];
  c.b[C::index(0, 3, 0)] = p[1];
  c.b[C::index(0, 0, 3)] = p[2];
  c.b[C::index(2, 1, 0)] = pn_tangent_point(p[0], n[0], p[1]);
  c.b[C::index(2, 0, 1)] = pn_tangent_point(p[0], n[0], p[2]);
  c.b[C::index(0, 2, 1)] = pn_tangent_point(p[1], n[1], p[2]);
  c.b[C::index(1, 2, 0)] = pn_tangent_point(p[1], n[1], p[0]);
  c.b[C::index(1, 0, 2)] = pn_tangent_point(p[2], n[2], p[0]);
  c.b[C::index(0, 1, 2)] = pn_tangent_point(p[2], n[2], p[1]);
  // The sum in PnTcs's order (corner by corner, towards the next corner first).
  Vec3<T> e(T(0)), v(T(0));
  const int next[3] = {C::index(2, 1, 0), C::index(0, 2, 1), C::index(1, 0, 2)};
  const int prev[3] = {C::index(2, 0, 1), C::index(1, 2, 0), C::index(0, 1, 2)};
  for (int i = 0; i < 3; ++i) {
    e += c.b[next[i]] + c.b[prev[i]];
    v += p[i];
  }
  e /= T(6);
  v /= T(3);
  c.b[C::index(1, 1, 1)] = e + (e - v) / T(2);
  return c;
}

namespace {

// A degree-m net as a function of (i, j, k); Bernstein sums over it.
constexpr int net_index(int m, int i, int k) { return (m - i) * (m - i + 1) / 2 + k; }

template <class T>
T power(T x, int e) {
  T r(1);
  for (int q = 0; q < e; ++q) r *= x;
  return r;
}

// sum over i+j+k=m of c[i,j,k] m!/(i!j!k!) w^i u^j v^k.
template <class T, class Coeff>
Vec3<T> bernstein_sum(int m, T w, T u, T v, Coeff&& c) {
  static constexpr int kFactorial[] = {1, 1, 2, 6};
  Vec3<T> s(T(0));
  for (int i = 0; i <= m; ++i)
    for (int j = 0; i + j <= m; ++j) {
      const int k = m - i - j;
      const T weight = T(kFactorial[m] / (kFactorial[i] * kFactorial[j] * kFactorial[k])) *
                       power(w, i) * power(u, j) * power(v, k);
      s += weight * c(i, j, k);
    }
  return s;
}

// Position and derivatives of a degree-m net (m = 2 or 3) given as b(i, j, k). Along u weight
// moves from corner 0 to corner 1: d/du = m sum_(m-1) (b_i,j+1,k - b_i+1,j,k) B^(m-1)_ijk.
template <class T, class Net>
SurfacePoint<T> evaluate_net(int m, T u, T v, Net&& b) {
  const T w = T(1) - u - v;
  auto du = [&](int i, int j, int k) { return b(i, j + 1, k) - b(i + 1, j, k); };
  auto dv = [&](int i, int j, int k) { return b(i, j, k + 1) - b(i + 1, j, k); };
  SurfacePoint<T> s;
  s.position = bernstein_sum(m, w, u, v, b);
  s.du = T(m) * bernstein_sum(m - 1, w, u, v, du);
  s.dv = T(m) * bernstein_sum(m - 1, w, u, v, dv);
  const T m2 = T(m * (m - 1));
  s.duu = m2 * bernstein_sum(m - 2, w, u, v, [&](int i, int j, int k) {
            return du(i, j + 1, k) - du(i + 1, j, k);
          });
  s.duv = m2 * bernstein_sum(m - 2, w, u, v, [&](int i, int j, int k) {
            return du(i, j, k + 1) - du(i + 1, j, k);
          });
  s.dvv = m2 * bernstein_sum(m - 2, w, u, v, [&](int i, int j, int k) {
            return dv(i, j, k + 1) - dv(i + 1, j, k);
          });
  return s;
}

}  // namespace

template <class T>
SurfacePoint<T> evaluate(const CubicNet<T>& net, T u, T v) {
  static_assert(CubicNet<T>::index(1, 1, 1) == net_index(3, 1, 1));
  return evaluate_net<T>(3, u, v, [&](int i, int, int k) { return net.b[net_index(3, i, k)]; });
}

template <class T>
SurfacePoint<T> evaluate(const QuadraticNet<T>& net, T u, T v) {
  static_assert(QuadraticNet<T>::index(0, 1, 1) == net_index(2, 0, 1));
  return evaluate_net<T>(2, u, v, [&](int i, int, int k) { return net.b[net_index(2, i, k)]; });
}

template <class T>
Vec3<T> analytic_normal(const SurfacePoint<T>& s) {
  const Vec3<T> c = glm::cross(s.du, s.dv);
  const T len2 = glm::dot(c, c);
  if (!(len2 > T(0)) || !(len2 < std::numeric_limits<T>::infinity())) return Vec3<T>(T(0));
  return c / std::sqrt(len2);
}

#define TESSREF_INSTANTIATE(T)                                                                        \
  template Vec3<T> tangent_plane_projection(const Vec3<T>&, const Vec3<T>&, const Vec3<T>&);         \
  template Vec3<T> pn_tangent_point(const Vec3<T>&, const Vec3<T>&, const Vec3<T>&);                 \
  template Vec3<T> phong_edge_point(const Vec3<T>&, const Vec3<T>&, const Vec3<T>&, const Vec3<T>&, \
                                    T);                                                              \
  template Vec3<T> nlsa_edge_point(const Vec3<T>&, const Vec3<T>&, const Vec3<T>&, const Vec3<T>&); \
  template Vec3<T> nagata_curvature(const Vec3<T>&, const Vec3<T>&, const Vec3<T>&, const Vec3<T>&, \
                                    T);                                                              \
  template Vec3<T> nagata_edge_point(const Vec3<T>&, const Vec3<T>&, const Vec3<T>&,                 \
                                     const Vec3<T>&, T);                                             \
  template Vec3<T> quadratic_normal_mid(const Vec3<T>&, const Vec3<T>&, const Vec3<T>&,              \
                                        const Vec3<T>&, bool);                                       \
  template QuadraticNet<T> quadratic_net(Interpolant, const Vec3<T>[3], const Vec3<T>[3],            \
                                         const InterpolantParams&);                                  \
  template CubicNet<T> elevate(const QuadraticNet<T>&);                                              \
  template CubicNet<T> cubic_net(Interpolant, const Vec3<T>[3], const Vec3<T>[3],                    \
                                 const InterpolantParams&);                                          \
  template SurfacePoint<T> evaluate(const CubicNet<T>&, T, T);                                       \
  template SurfacePoint<T> evaluate(const QuadraticNet<T>&, T, T);                                   \
  template Vec3<T> analytic_normal(const SurfacePoint<T>&);

TESSREF_INSTANTIATE(float)
TESSREF_INSTANTIATE(double)
#undef TESSREF_INSTANTIATE

}  // namespace tessref::schemes
