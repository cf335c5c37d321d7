#pragma once
// The four local C0 interpolants of seed 004 (Boschiroli et al.) in one Bézier form: curved PN
// triangles (cubic), Phong tessellation, NLSA and Nagata triangles (quadratic). Pure math, in
// float or double, with no pipeline types: the built-in programs (phong.h, nlsa.h, nagata.h) call
// the per-edge rules below, and surface statistics evaluate the nets. Formulas: shared notes
// formulas.md; seed 004 Sec. 2 (and its typos are not followed).
//
// Conventions. A triangle p[0], p[1], p[2] with unit normals n[0], n[1], n[2] (callers normalize).
// A degree-m net holds b_ijk, i + j + k = m, where i is the power of corner 0's weight, j of
// corner 1's, k of corner 2's. Parameters (u, v) give the corner weights (1 - u - v, u, v):
//   s(u, v) = sum over i+j+k=m of b_ijk m!/(i! j! k!) (1-u-v)^i u^j v^k.
#include <glm/glm.hpp>

namespace tessref::schemes {

enum class Interpolant { PN, Phong, NLSA, Nagata };
const char* to_string(Interpolant s);  // "pn" | "phong" | "nlsa" | "nagata"

// Nagata's threshold (seed 004 Sec. 2.3): c1 = 0 when dc <= eps or 1 - dc <= eps, where
// dc = (1 - n0.n1)/2 = sin^2(angle/2). The default 1e-4 (normals within 1.15 degrees of parallel or
// antiparallel) is the smallest that keeps dc meaningful in single precision: n0.n1 of two unit
// float normals carries an error of about 1e-7, so below 1e-4 dc loses its third digit and c1,
// which divides by it, turns into noise (an edge whose normals agree to float precision but
// which leans against them gets a random bulge of the edge's size). It removes that numerical
// blow-up only: the geometric one (tangent planes nearly parallel, their intersection line far
// away) needs larger values; seed 004 uses 0.04 on real meshes and 0 on the sphere and torus.
inline constexpr double kDefaultNagataEps = 1e-4;

struct InterpolantParams {
  double phong_alpha = 0.75;  // Boubekeur & Alexa's shape factor: 0 flat, 1 full projection
  double nagata_eps = kDefaultNagataEps;
};

template <class T>
using Vec3 = glm::vec<3, T, glm::defaultp>;

// Cubic Bézier triangle; control point b[index(i, j, k)], i + j + k = 3.
template <class T>
struct CubicNet {
  Vec3<T> b[10];
  // Rows by falling i, k rising within a row: 300, 210, 201, 120, 111, 102, 030, 021, 012, 003.
  static constexpr int index(int i, int j, int k) { return (void)j, (3 - i) * (4 - i) / 2 + k; }
};

// Quadratic Bézier triangle; b[index(i, j, k)], i + j + k = 2: 200, 110, 101, 020, 011, 002.
template <class T>
struct QuadraticNet {
  Vec3<T> b[6];
  static constexpr int index(int i, int j, int k) { return (void)j, (2 - i) * (3 - i) / 2 + k; }
};

// ---- Per-edge rules. Each uses only its edge's two points and normals, so both patches of an
// edge compute the same control point; each is written symmetric in its two ends (swapping
// (p0, n0) and (p1, n1) gives the same bits), which keeps shared edges watertight bit for bit.

// pi_n(q): q projected into the tangent plane through p with normal n: q - ((q - p).n) n.
template <class T>
Vec3<T> tangent_plane_projection(const Vec3<T>& q, const Vec3<T>& p, const Vec3<T>& n);

// PN (Vlachos et al.): the cubic tangent coefficient next to pi on the edge towards pj,
// (2 pi + pj - ((pj - pi).ni) ni) / 3 (b210 for i = 0, j = 1). Not symmetric: it is one end's.
template <class T>
Vec3<T> pn_tangent_point(const Vec3<T>& pi, const Vec3<T>& ni, const Vec3<T>& pj);

// Phong tessellation (Boubekeur & Alexa 2008; seed 004 Eq. 2), the quadratic b110:
// m + alpha ((pi_0(p1) + pi_1(p0))/2 - m), m = (p0 + p1)/2.
template <class T>
Vec3<T> phong_edge_point(const Vec3<T>& p0, const Vec3<T>& n0, const Vec3<T>& p1,
                         const Vec3<T>& n1, T alpha);

// NLSA (Barrera et al. 2002; seed 004 Sec. 2.4), the quadratic b110 from its own tangents:
// t0 = n1 - l n0, t1 = l n1 - n0 (l = n0.n1, Gram-Schmidt), d = p1 - p0,
// b110 = (p0 + p1)/2 + ((d.t0 / t0.t0) t0 - (d.t1 / t1.t1) t1) / 4.
// The tangents vanish for parallel normals: where t0.t0 or t1.t1 is at most T's machine epsilon
// (normals within about sqrt(eps) radians: 3.5e-4 in float) the bracket is the parallel limit,
// zero, and b110 the edge midpoint (Phong(1/2) gives that too). Equal to phong_edge_point with
// alpha = 1/2 up to rounding (seed 004 Sec. 2.4).
template <class T>
Vec3<T> nlsa_edge_point(const Vec3<T>& p0, const Vec3<T>& n0, const Vec3<T>& p1,
                        const Vec3<T>& n1);

// Nagata (2005; seed 004 Eq. 3): the curvature coefficient of the edge curve
// x(t) = p0 + (d - c1) t + c1 t^2, d = p1 - p0, with x'(0) orthogonal to n0 and x'(1) to n1:
//   nu = (n0 + n1)/2, dnu = (n0 - n1)/2, dv = d.nu, dd = d.dnu, dc = (1 - n0.n1)/2,
//   c1 = (dd / (1 - dc)) nu + (dv / dc) dnu,
// and c1 = 0 when dc <= eps or 1 - dc <= eps (seed 004's threshold; NaN too). dc is computed
// from n0.n1 (seed 004 writes n0.dnu, the same for unit normals) so that it is symmetric.
// Swapping the ends leaves c1 as it is (d and dnu both change sign), as the reversed curve
// x(1 - t) = p1 + (-d - c1) t + c1 t^2 requires.
template <class T>
Vec3<T> nagata_curvature(const Vec3<T>& p0, const Vec3<T>& n0, const Vec3<T>& p1,
                         const Vec3<T>& n1, T eps);
// The quadratic b110 = (p0 + p1)/2 - c1/2.
template <class T>
Vec3<T> nagata_edge_point(const Vec3<T>& p0, const Vec3<T>& n0, const Vec3<T>& p1,
                          const Vec3<T>& n1, T eps);

// Quadratic normal patch (Vlachos et al.; seed 004 Sec. 4, applicable to every scheme): the
// mid-edge normal coefficient, the average normal reflected across the plane perpendicular to
// the edge: h = n0 + n1 - v d, v = k d.(n0 + n1) / d.d with k = 2, normalized (Vlachos), or
// k = 4 and not normalized (corrected, seed 001 App. A). A zero-length edge keeps n0 + n1.
// The normalization of h is the caller's (GLSL twins' safe_normalize).
template <class T>
Vec3<T> quadratic_normal_mid(const Vec3<T>& p0, const Vec3<T>& n0, const Vec3<T>& p1,
                             const Vec3<T>& n1, bool corrected);

// ---- Nets.

// The quadratic net of Phong (params.phong_alpha), NLSA or Nagata (params.nagata_eps): corners
// p[i], mid-edge points from the rules above. Throws std::invalid_argument for PN (cubic).
template <class T>
QuadraticNet<T> quadratic_net(Interpolant s, const Vec3<T> p[3], const Vec3<T> n[3],
                              const InterpolantParams& params);

// Degree elevation: b_ijk = (i q_(i-1)jk + j q_i(j-1)k + k q_ij(k-1)) / 3; the same surface.
template <class T>
CubicNet<T> elevate(const QuadraticNet<T>& q);

// The patch of any scheme as a cubic net: PN as pn_triangles.cpp builds it (tangent coefficients,
// b111 = E + (E - V)/2), the quadratic schemes elevated.
template <class T>
CubicNet<T> cubic_net(Interpolant s, const Vec3<T> p[3], const Vec3<T> n[3],
                      const InterpolantParams& params);

// ---- Evaluation. Position and first and second partial derivatives along u and v.
template <class T>
struct SurfacePoint {
  Vec3<T> position, du, dv, duu, duv, dvv;
};

template <class T>
SurfacePoint<T> evaluate(const CubicNet<T>& net, T u, T v);
template <class T>
SurfacePoint<T> evaluate(const QuadraticNet<T>& net, T u, T v);

// normalize(du x dv): the patch's own normal, oriented by the corner order p0 -> p1 -> p2 (for
// a counter-clockwise triangle, the side its face normal points to). Zero where du x dv is.
template <class T>
Vec3<T> analytic_normal(const SurfacePoint<T>& s);

}  // namespace tessref::schemes
