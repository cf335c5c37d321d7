// The executor's run loop and instruction kernels (see executor.h for the model).
#include "shader/executor.h"

#include <algorithm>
#include <atomic>
#include <unordered_map>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

#include <spirv/unified1/GLSL.std.450.h>

#include "shader/executor_runner.h"
#include "texture/sample.h"
#include "shader/nan_trace.h"

namespace tessref::shader {

std::unique_ptr<DecodedProgram> decode_program(const Module& m);  // executor_decode.cpp

void Runner::compare(const XIns& x) {
  auto cmp = [&](auto zero, auto f) {
    using T = decltype(zero);
    map2<T, std::uint32_t>(x, [&](T a, T b) { return std::uint32_t(f(a, b)); });
  };
  auto fcmp = [&](auto f) {
    if (x.s == Scalar::F64) cmp(double{}, f);
    else cmp(float{}, f);
  };
  auto unord = [](auto f) {
    return [f](auto a, auto b) { return std::isnan(a) || std::isnan(b) || f(a, b); };
  };
  switch (x.op) {
    case XOp::OrdEq: fcmp([](auto a, auto b) { return a == b; }); break;
    case XOp::OrdNe: fcmp([](auto a, auto b) { return a < b || a > b; }); break;
    case XOp::OrdLt: fcmp([](auto a, auto b) { return a < b; }); break;
    case XOp::OrdGt: fcmp([](auto a, auto b) { return a > b; }); break;
    case XOp::OrdLe: fcmp([](auto a, auto b) { return a <= b; }); break;
    case XOp::OrdGe: fcmp([](auto a, auto b) { return a >= b; }); break;
    case XOp::UnordEq: fcmp(unord([](auto a, auto b) { return a == b; })); break;
    case XOp::UnordNe: fcmp([](auto a, auto b) { return !(a == b); }); break;
    case XOp::UnordLt: fcmp(unord([](auto a, auto b) { return a < b; })); break;
    case XOp::UnordGt: fcmp(unord([](auto a, auto b) { return a > b; })); break;
    case XOp::UnordLe: fcmp(unord([](auto a, auto b) { return a <= b; })); break;
    case XOp::UnordGe: fcmp(unord([](auto a, auto b) { return a >= b; })); break;
    case XOp::IEq: cmp(std::uint32_t{}, [](auto a, auto b) { return a == b; }); break;
    case XOp::INe: cmp(std::uint32_t{}, [](auto a, auto b) { return a != b; }); break;
    case XOp::SLt: cmp(std::int32_t{}, [](auto a, auto b) { return a < b; }); break;
    case XOp::SGt: cmp(std::int32_t{}, [](auto a, auto b) { return a > b; }); break;
    case XOp::SLe: cmp(std::int32_t{}, [](auto a, auto b) { return a <= b; }); break;
    case XOp::SGe: cmp(std::int32_t{}, [](auto a, auto b) { return a >= b; }); break;
    case XOp::ULt: cmp(std::uint32_t{}, [](auto a, auto b) { return a < b; }); break;
    case XOp::UGt: cmp(std::uint32_t{}, [](auto a, auto b) { return a > b; }); break;
    case XOp::ULe: cmp(std::uint32_t{}, [](auto a, auto b) { return a <= b; }); break;
    case XOp::UGe: cmp(std::uint32_t{}, [](auto a, auto b) { return a >= b; }); break;
    default: break;
  }
}

void Runner::access_chain(const XIns& x) {
  const Chain& ch = p.chains[x.aux];
  std::uint32_t* dst = A + std::size_t(x.dst) * L;
  const std::uint32_t* base = x.a == kNone ? nullptr : A + std::size_t(x.a) * L;
  const std::uint32_t constant = ch.steps[0].offset;
  auto step_offset = [&](const ChainStep& s, std::uint32_t raw) {
    // Robust access: an index outside the array reads or writes its last (or first) element.
    std::int64_t k = s.index_scalar == Scalar::I32 ? std::int64_t(std::int32_t(raw)) : std::int64_t(raw);
    k = std::clamp<std::int64_t>(k, 0, s.length ? s.length - 1 : 0);
    return std::uint32_t(k) * s.stride;
  };
  // The same indices in every active lane (the common case): one offset for all.
  std::uint32_t uniform = base ? uniform_offset(base) : 0u;
  for (std::size_t i = 1; i < ch.steps.size() && uniform != kNone; ++i) {
    const std::uint32_t index = uniform_offset(A + std::size_t(ch.steps[i].index_reg) * L);
    uniform = index == kNone ? kNone : uniform + step_offset(ch.steps[i], index);
  }
  if (uniform != kNone) {
    const std::uint32_t value = uniform + constant;
    put(dst, [&](int) { return value; });
    return;
  }
  put(dst, [&](int l) {
    std::uint32_t off = (base ? base[l] : 0u) + constant;
    for (std::size_t i = 1; i < ch.steps.size(); ++i)
      off += step_offset(ch.steps[i], A[std::size_t(ch.steps[i].index_reg) * L + l]);
    return off;
  });
}

// The offset every active lane has in a pointer row, or kNone when they differ. Dynamic indices
// are mostly the same in all lanes of a batch (a TES batch is one patch), and a constant offset
// makes a load a row copy or a broadcast instead of a gather.
// The value every active lane in [lo, hi) has in row, or kNone (also when none is active).
std::uint32_t Runner::uniform_in(const std::uint32_t* row, int lo, int hi) const {
  std::uint32_t value = kNone;
  for (int l = lo; l < hi; ++l)
    if (full || mask[l]) {
      if (value == kNone) value = row[l];
      else if (row[l] != value) return kNone;
    }
  return value;
}

std::uint32_t Runner::uniform_offset(const std::uint32_t* off) const {
  const int count = n;
  if (full) {  // a min and max reduction, which vectorizes
    std::uint32_t lo = off[0], hi = off[0];
    for (int l = 1; l < count; ++l) {
      lo = std::min(lo, off[l]);
      hi = std::max(hi, off[l]);
    }
    return lo == hi ? lo : kNone;
  }
  return uniform_in(off, 0, count);
}

void Runner::load(const XIns& x) {
  const Access& a = p.accesses[x.aux];
  const VariableSlot& v = p.slots[a.slot];
  const std::uint32_t* off = a.offset_reg == kNone ? nullptr : A + std::size_t(a.offset_reg) * L;
  std::uint32_t offset = a.offset;  // the constant part; a dynamic offset all lanes share joins it
  if (off)
    if (const std::uint32_t u = uniform_offset(off); u != kNone) {
      offset += u;
      off = nullptr;
    }
  for (const FlatComponent& c : a.flat) {
    if (c.scalar == Scalar::F64) {
      double* d = row<double>(x.dst + c.word);
      if (v.per_lane) {
        put(d, [&](int l) {
          const std::uint32_t o = (off ? off[l] : 0u) + offset + c.word;
          return reinterpret_cast<const double*>(A + std::size_t(v.base + o) * L)[l];
        });
      } else {
        put(d, [&](int l) {
          double r;
          std::memcpy(&r, common(a.slot, l) + (off ? off[l] : 0u) + offset + c.word, 8);
          return r;
        });
      }
      continue;
    }
    std::uint32_t* d = A + std::size_t(x.dst + c.word) * L;
    if (v.per_lane) {
      if (!off) {
        const std::uint32_t* s = A + std::size_t(v.base + offset + c.word) * L;
        put(d, [&](int l) { return s[l]; });
      } else {
        put(d, [&](int l) { return A[std::size_t(v.base + off[l] + offset + c.word) * L + l]; });
      }
    } else {
      const std::uint32_t* s = (v.per_group ? inv.shared_.data() + v.base : common(a.slot)) + offset + c.word;
      if (v.per_group && inv.groups_ > 1) {  // each lane its group's copy
        // A broadcast per group where the group's lanes share the offset (a group's lanes are
        // consecutive), else a gather.
        const std::uint32_t* g = inv.group_base_;
        for (int k = 0; k < num_group_runs; ++k) {
          const auto [lo, hi] = group_runs[k];
          const std::uint32_t u = off ? uniform_in(off, lo, hi) : 0u;
          if (u != kNone) {
            put_range(d, lo, hi, s[g[lo] + u]);
          } else {
            for (int l = lo; l < hi; ++l)
              if (full || mask[l]) d[l] = s[g[l] + off[l]];
          }
        }
        continue;
      }
      if (v.per_group) s += inv.group_base_[0];
      if (!off) {
        const std::uint32_t value = *s;
        put(d, [&](int) { return value; });
      } else {
        put(d, [&](int l) { return s[off[l]]; });
      }
    }
  }
}

void Runner::store(const XIns& x) {
  const Access& a = p.accesses[x.aux];
  const VariableSlot& v = p.slots[a.slot];
  const std::uint32_t* off = a.offset_reg == kNone ? nullptr : A + std::size_t(a.offset_reg) * L;
  // A per-lane variable at a constant offset: row copies.
  if (!off && v.per_lane) {
    copy_rows(A + std::size_t(v.base + a.offset) * L, A + std::size_t(x.a) * L, a.words, doubles_of(a.doubles));
    return;
  }
  // Lane by lane in increasing order: where lanes write one shared word, the last lane's value stays.
  for (const FlatComponent& c : a.flat) {
    const int w = scalar_words(c.scalar);
    for (int l = 0; l < n; ++l) {
      if (!mask[l] || (v.storage && inv.helper_[l])) continue;
      const std::uint32_t o = (off ? off[l] : 0u) + a.offset + c.word;
      const std::uint32_t* src = A + std::size_t(x.a + c.word) * L + std::size_t(l) * w;
      std::uint32_t* dst = v.per_lane ? A + std::size_t(v.base + o) * L + std::size_t(l) * w : common(a.slot, l) + o;
      dst[0] = src[0];
      if (w == 2) dst[1] = src[1];
    }
  }
}

void Runner::matrix(const XIns& x) {
  // Columns of a: x.aux, rows of a: x.m; columns of b: x.d. Sums run in index order, as glm's,
  // except mat4 * vec4, which glm (and so the built-in programs) sums as (c0 + c1) + (c2 + c3).
  auto go = [&](auto zero) {
    using T = decltype(zero);
    const std::uint32_t ca = x.aux, ra = x.m;
    auto a = [&](std::uint32_t col, std::uint32_t r) { return row<T>(x.a, col * ra + r); };
    switch (x.op) {
      case XOp::MatTimesVec:  // (ra x ca) * vec(ca) -> vec(ra)
        if (ca == 4 && ra == 4) {
          for (std::uint32_t r = 0; r < 4; ++r)
            put(row<T>(x.dst, r), [&](int l) {
              const T p0 = a(0, r)[l] * row<T>(x.b, 0)[l], p1 = a(1, r)[l] * row<T>(x.b, 1)[l];
              const T p2 = a(2, r)[l] * row<T>(x.b, 2)[l], p3 = a(3, r)[l] * row<T>(x.b, 3)[l];
              return (p0 + p1) + (p2 + p3);
            });
          break;
        }
        for (std::uint32_t r = 0; r < ra; ++r)
          put(row<T>(x.dst, r), [&](int l) {
            T s = a(0, r)[l] * row<T>(x.b, 0)[l];
            for (std::uint32_t c = 1; c < ca; ++c) s = s + a(c, r)[l] * row<T>(x.b, c)[l];
            return s;
          });
        break;
      case XOp::VecTimesMat: {  // vec(rb) * (rb x cb) -> vec(cb); a is the vector (ra comps)
        const std::uint32_t cb = x.d;
        for (std::uint32_t c = 0; c < cb; ++c)
          put(row<T>(x.dst, c), [&](int l) {
            T s = row<T>(x.a, 0)[l] * row<T>(x.b, c * ra)[l];
            for (std::uint32_t r = 1; r < ra; ++r) s = s + row<T>(x.a, r)[l] * row<T>(x.b, c * ra + r)[l];
            return s;
          });
        break;
      }
      case XOp::MatTimesMat: {  // (ra x ca) * (ca x cb) -> (ra x cb)
        const std::uint32_t cb = x.d;
        for (std::uint32_t j = 0; j < cb; ++j)
          for (std::uint32_t r = 0; r < ra; ++r)
            put(row<T>(x.dst, j * ra + r), [&](int l) {
              T s = a(0, r)[l] * row<T>(x.b, j * ca)[l];
              for (std::uint32_t c = 1; c < ca; ++c) s = s + a(c, r)[l] * row<T>(x.b, j * ca + c)[l];
              return s;
            });
        break;
      }
      case XOp::OuterProduct:  // vec(ra) * vec(cb)^T -> (ra x cb)
        for (std::uint32_t j = 0; j < x.d; ++j)
          for (std::uint32_t r = 0; r < ra; ++r)
            put(row<T>(x.dst, j * ra + r), [&](int l) { return row<T>(x.a, r)[l] * row<T>(x.b, j)[l]; });
        break;
      case XOp::Transpose:  // (ra x ca) -> (ca x ra)
        for (std::uint32_t c = 0; c < ca; ++c)
          for (std::uint32_t r = 0; r < ra; ++r) {
            const T* s = a(c, r);
            put(row<T>(x.dst, r * ca + c), [&](int l) { return s[l]; });
          }
        break;
      default: break;
    }
  };
  if (x.s == Scalar::F64) go(double{});
  else go(float{});
}

void Runner::derivative(const XIns& x) {
  // Lane 4q + k is pixel (k & 1, k >> 1) of quad q. Every derivative is the fine one, a difference
  // per row (dFdx) or column (dFdy), as llvmpipe computes dFdx, dFdxCoarse and dFdxFine alike
  // (measured: tests/glref/draws_vs_llvmpipe_test.cpp); GL lets coarse ones be computed so.
  const bool is_x = x.op == XOp::DPdx;
  const bool is_w = x.op == XOp::Fwidth;
  for (std::uint32_t c = 0; c < x.n; ++c) {
    const float* a = row<float>(x.a, c);
    auto dx = [&](int l) {
      const int q = l & ~3, k = l & 2;
      return a[q + k + 1] - a[q + k];
    };
    auto dy = [&](int l) {
      const int q = l & ~3, k = l & 1;
      return a[q + k + 2] - a[q + k];
    };
    put(row<float>(x.dst, c), [&](int l) {
      if (l - (l & 3) + 3 >= n) return 0.0f;
      if (is_w) return std::fabs(dx(l)) + std::fabs(dy(l));
      return is_x ? dx(l) : dy(l);
    });
  }
}

void Runner::texture(const XIns& x) {
  using Kind = TexOp::Kind;
  const TexOp& op = p.textures[x.aux];
  if (op.storage) {
    image(x);
    return;
  }
  const std::uint32_t* unit = row<std::uint32_t>(op.image);
  auto bound = [&](int l) -> const texture::Texture* {
    const std::uint32_t u = unit[l];
    return u < inv.textures_.size() ? inv.textures_[u] : nullptr;
  };
  static const texture::Texture kUnbound;  // no levels: incomplete, reads (0, 0, 0, 1)
  // A unit holds a texture per target: a 2D array sampler on a unit with a 2D texture reads the
  // unit's empty GL_TEXTURE_2D_ARRAY binding, and so on.
  auto tex = [&](int l) -> const texture::Texture& {
    const texture::Texture* t = bound(l);
    return t && t->target == op.target ? *t : kUnbound;
  };
  // Coordinates within a layer (1 to 3; a cube map's direction); an array's layer coordinate comes after them.
  const std::uint32_t dims = std::uint32_t(texture::lookup_dimensions(op.target));
  const bool cube = texture::is_cube(op.target);
  const bool arrayed = texture::is_array(op.target);
  auto irow = [&](std::uint32_t r, std::uint32_t c, int l) { return std::int32_t(row<std::uint32_t>(r, c)[l]); };
  auto frow = [&](std::uint32_t r, std::uint32_t c, int l) { return row<float>(r, c)[l]; };
  // textureOffset's (or texelFetchOffset's) component c: 0 without one, or past the target's.
  auto offset = [&](std::uint32_t c, int l) { return op.offset == kNone || c >= dims ? 0 : irow(op.offset, c, l); };

  if (op.kind == Kind::QuerySize || op.kind == Kind::QueryLevels) {
    for (int l = 0; l < n; ++l) {
      if (!mask[l]) continue;
      int size[3];  // width, height, layers
      texture::level_size(tex(l), op.lod == kNone ? 0 : irow(op.lod, 0, l), size);
      if (op.kind == Kind::QueryLevels) row<std::uint32_t>(x.dst)[l] = std::uint32_t(texture::query_levels(tex(l)));
      else
        for (std::uint32_t c = 0; c < x.n && c < 3; ++c) row<std::uint32_t>(x.dst, c)[l] = std::uint32_t(size[c]);
    }
    return;
  }
  if (op.kind == Kind::Fetch) {
    for (int l = 0; l < n; ++l) {
      if (!mask[l]) continue;
      float texel[4];
      // The offset is added in 64 bits by fetch's bounds check: no overflow at INT_MAX.
      auto at = [&](std::uint32_t c) {  // component c with its offset; 0 past the coordinate's
        return c < dims ? std::int64_t(irow(op.coord, c, l)) + offset(c, l) : 0;
      };
      const std::int64_t i = at(0), j = at(1), k = at(2);
      const bool inside = i >= 0 && j >= 0 && k >= 0 && i <= 0x7fffffff && j <= 0x7fffffff && k <= 0x7fffffff;
      // Outside int's range: a texel no level has. The layer: an array's, or a 3D texture's slice.
      const int layer = arrayed ? irow(op.coord, dims, l) : inside ? int(k) : -1;
      texture::fetch(tex(l), inside ? int(i) : -1, inside ? int(j) : -1, layer, op.lod == kNone ? 0 : irow(op.lod, 0, l),
                     texel);
      for (std::uint32_t c = 0; c < x.n; ++c) row<float>(x.dst, c)[l] = texel[c];
    }
    return;
  }
  // Sample, Gather and QueryLod: the coordinates and reference depth, projected for the Proj forms.
  float s[L], t[L], r[L], dref[L];
  int layer[L];  // an array's layer (texture::array_layer), else 0
  for (int l = 0; l < n; ++l) {
    s[l] = frow(op.coord, 0, l);
    t[l] = dims >= 2 ? frow(op.coord, 1, l) : 0.0f;
    r[l] = dims == 3 ? frow(op.coord, 2, l) : 0.0f;
    // textureQueryLod takes the coordinates within a layer alone.
    layer[l] = arrayed && op.kind != Kind::QueryLod ? texture::array_layer(tex(l), frow(op.coord, dims, l)) : 0;
    dref[l] = op.dref == kNone ? 0.0f : frow(op.dref, 0, l);
    if (op.proj) {  // times 1/q, as Mesa lowers the projection (nir_lower_tex)
      const float inv_q = 1.0f / frow(op.coord, op.coord_comps - 1, l);
      s[l] = s[l] * inv_q;
      t[l] = t[l] * inv_q;
      r[l] = r[l] * inv_q;
      dref[l] = dref[l] * inv_q;
    }
  }
  const bool shadow = op.dref != kNone;
  if (op.kind == Kind::Gather) {
    for (int l = 0; l < n; ++l) {
      if (!mask[l]) continue;
      const int component = op.component == kNone ? 0 : irow(op.component, 0, l) & 3;
      float texel[4];
      if (op.offsets != kNone) {
        // textureGatherOffsets: texel i0 j0 (the fourth) of each offset's footprint, as Mesa
        // lowers it (nir_lower_tex's tg4 offsets).
        for (int k = 0; k < 4; ++k) {
          float one[4];
          const texture::Coords at{s[l], t[l], r[l], layer[l], irow(op.offsets, std::uint32_t(2 * k), l),
                                   irow(op.offsets, std::uint32_t(2 * k + 1), l)};
          texture::gather(tex(l), at, component, shadow ? &dref[l] : nullptr, inv.seamless_cube_, one);
          texel[k] = one[3];
        }
      } else {
        const texture::Coords at{s[l], t[l], r[l], layer[l], offset(0, l), offset(1, l)};
        texture::gather(tex(l), at, component, shadow ? &dref[l] : nullptr, inv.seamless_cube_, texel);
      }
      for (std::uint32_t c = 0; c < x.n; ++c) row<float>(x.dst, c)[l] = texel[c];
    }
    return;
  }
  // Each lane's LOD input: the explicit LOD or gradients; for an implicit LOD in a fragment shader
  // the quad's derivatives, from its top-left pixel (lane 4q, whose right and upper neighbours
  // are lanes 4q + 1 and 4q + 2), one LOD for the quad as llvmpipe computes it; elsewhere LOD 0
  // plus the bias (GLSL 4.60 8.9: no implicit derivatives outside fragment shaders). A cube map
  // with a mip filter or a bias, or queried, takes each lane's own (fine) derivatives instead, as
  // llvmpipe.
  // Filled in place: a struct built on the stack and copied into the array stalled on
  // store-to-load forwarding (its bool fields written as bytes, read back in 16-byte moves).
  auto lod_input = [&](int l, texture::LodInput& in) {
    in = texture::LodInput{};
    in.cube_dir[0] = s[l], in.cube_dir[1] = t[l], in.cube_dir[2] = r[l];
    if (op.lod != kNone) {
      in.lod = frow(op.lod, 0, l);
    } else if (op.grad_x != kNone) {
      in.from = texture::LodInput::From::Derivatives;
      in.gradients = true;
      in.dsdx = frow(op.grad_x, 0, l);
      in.dtdx = dims >= 2 ? frow(op.grad_x, 1, l) : 0.0f;
      in.drdx = dims == 3 ? frow(op.grad_x, 2, l) : 0.0f;
      in.dsdy = frow(op.grad_y, 0, l);
      in.dtdy = dims >= 2 ? frow(op.grad_y, 1, l) : 0.0f;
      in.drdy = dims == 3 ? frow(op.grad_y, 2, l) : 0.0f;
    } else if (p.fragment && (l | 3) < n) {
      in.has_bias = op.bias != kNone;
      in.bias = in.has_bias ? frow(op.bias, 0, l) : 0.0f;
      const bool own = cube && (op.kind == Kind::QueryLod || texture::cube_lod_per_invocation(tex(l), in.has_bias));
      // The differences along x and y from lanes (x0, y) and (x, y0) of the quad: the lane's own
      // row and column, or the top-left lane's.
      const int q = l & ~3, x0 = own ? q + (l & 2) : q, y0 = own ? q + (l & 1) : q;
      in.from = texture::LodInput::From::Derivatives;
      in.dsdx = s[x0 + 1] - s[x0];
      in.dtdx = t[x0 + 1] - t[x0];
      in.drdx = r[x0 + 1] - r[x0];
      in.dsdy = s[y0 + 2] - s[y0];
      in.dtdy = t[y0 + 2] - t[y0];
      in.drdy = r[y0 + 2] - r[y0];
      in.per_quad = !in.has_bias && !own;
      if (!own) in.cube_dir[0] = s[q], in.cube_dir[1] = t[q], in.cube_dir[2] = r[q];
    } else {
      in.lod = op.bias != kNone ? 0.0f + frow(op.bias, 0, l) : 0.0f;
    }
  };
  // llvmpipe samples a vector of invocations at once, and when its filters differ for
  // minification and magnification, one invocation filtered linearly changes how the others are
  // filtered (texture::linear_in_vector). Its vectors are two quads of a fragment shader (the
  // caller's keys: Invocations::set_sampling_vectors), eight invocations of other stages, which
  // tessref takes one by one so that no result depends on which share a batch.
  auto vector_of = [&](int l) -> std::uint32_t {
    if (inv.has_sampling_vectors_) return inv.sampling_vector_[l];
    return p.fragment ? std::uint32_t(l / 4) : std::uint32_t(l);
  };
  texture::LodInput lods[L];
  for (int l = 0; l < n; ++l) lod_input(l, lods[l]);
  texture::SampleContext context[L];
  if (op.kind == Kind::Sample) {
    bool linear_lane[L] = {};
    bool any_linear = false;
    for (int l = 0; l < n; ++l) {
      linear_lane[l] = texture::linear_in_vector(tex(l), lods[l], inv.seamless_cube_);
      any_linear |= linear_lane[l];
      context[l].seamless_cube = inv.seamless_cube_;
    }
    for (int l = 0; any_linear && l < n; ++l)  // a vector's lanes are adjacent: at most 8
      for (int k = std::max(0, l - 7); k < std::min(n, l + 8) && !context[l].vector_linear; ++k)
        context[l].vector_linear = linear_lane[k] && vector_of(k) == vector_of(l);
    // A seamless cube map's corners: one lane's changes how its whole vector is filtered.
    if (cube && inv.seamless_cube_) {
      texture::CubeCorners corners[L];
      for (int l = 0; l < n; ++l)
        corners[l] = texture::cube_corners(tex(l), texture::Coords{s[l], t[l], r[l], layer[l]}, lods[l], context[l]);
      for (int l = 0; l < n; ++l)
        for (int k = std::max(0, l - 7); k < std::min(n, l + 8); ++k)
          if (vector_of(k) == vector_of(l))
            for (int level = 0; level < 2; ++level) context[l].vector_corner[level] |= corners[k].level[level];
    }
  }
  for (int l = 0; l < n; ++l) {
    if (!mask[l]) continue;
    const texture::LodInput& in = lods[l];
    if (op.kind == Kind::QueryLod) {
      float lod[2];
      texture::query_lod(tex(l), in, lod);
      for (std::uint32_t c = 0; c < x.n && c < 2; ++c) row<float>(x.dst, c)[l] = lod[c];
      continue;
    }
    float texel[4];
    const texture::Coords at{s[l], t[l], r[l], layer[l], offset(0, l), offset(1, l), offset(2, l)};
    texture::sample(tex(l), at, in, shadow ? &dref[l] : nullptr, texel, context[l]);
    for (std::uint32_t c = 0; c < x.n; ++c) row<float>(x.dst, c)[l] = texel[c];
  }
}

void Runner::atomic(const XIns& x) {
  // Lanes take their turns in lane order, so the values returned are deterministic. A helper
  // invocation's atomic changes nothing (GL 4.6 15.2.5) and returns the value it read.
  const Access& a = p.accesses[x.aux];
  const VariableSlot& v = p.slots[a.slot];
  const std::uint32_t* off = a.offset_reg == kNone ? nullptr : A + std::size_t(a.offset_reg) * L;
  std::uint32_t* result = x.dst == kNone ? nullptr : A + std::size_t(x.dst) * L;
  for (int l = 0; l < n; ++l) {
    if (!mask[l]) continue;
    const std::uint32_t o = (off ? off[l] : 0u) + a.offset;
    std::uint32_t* cell = v.per_lane ? A + std::size_t(v.base + o) * L + l : common(a.slot, l) + o;
    const std::uint32_t before = *cell;
    const std::uint32_t operand = x.a == kNone ? 0u : A[std::size_t(x.a) * L + l];
    const std::uint32_t comparator = x.b == kNone ? 0u : A[std::size_t(x.b) * L + l];
    const std::uint32_t after = atomic_value(x.op, before, operand, comparator);
    if (v.per_lane || !inv.helper_[l]) *cell = after;
    // atomicCounterDecrement returns the value after the decrement, the others the value before.
    if (result) result[l] = x.op == XOp::AtomicDec ? after : before;
  }
}

void Runner::exec(const XIns& x) {
  switch (x.op) {
    case XOp::Nop: break;
    case XOp::Copy: words_copy(x.dst, x.a, x.n, x.doubles); break;
    case XOp::Undef: {
      static const std::uint32_t zeros[4 * L] = {};  // copied from, a few rows at a time
      for (std::uint32_t w = 0; w < x.n; w += 2)
        copy_rows(A + std::size_t(x.dst + w) * L, zeros, std::min(2u, x.n - w), nullptr);
      break;
    }
    case XOp::Neg:
      arith(x, [&](auto z) {
        using T = decltype(z);
        if constexpr (std::is_integral_v<T>) map1<std::uint32_t, std::uint32_t>(x, [](std::uint32_t a) { return 0u - a; });
        else map1<T, T>(x, [](T a) { return -a; });
      });
      break;
    case XOp::Not: map1<std::uint32_t, std::uint32_t>(x, [](std::uint32_t a) { return ~a; }); break;
    case XOp::LogicalNot: map1<std::uint32_t, std::uint32_t>(x, [](std::uint32_t a) { return a ^ 1u; }); break;
    case XOp::Add:
      arith(x, [&](auto z) {
        using T = decltype(z);
        if constexpr (std::is_integral_v<T>) map2<std::uint32_t, std::uint32_t>(x, [](std::uint32_t a, std::uint32_t b) { return a + b; });
        else map2<T, T>(x, [](T a, T b) { return a + b; });
      });
      break;
    case XOp::Sub:
      arith(x, [&](auto z) {
        using T = decltype(z);
        if constexpr (std::is_integral_v<T>) map2<std::uint32_t, std::uint32_t>(x, [](std::uint32_t a, std::uint32_t b) { return a - b; });
        else map2<T, T>(x, [](T a, T b) { return a - b; });
      });
      break;
    case XOp::Mul:
      arith(x, [&](auto z) {
        using T = decltype(z);
        if constexpr (std::is_integral_v<T>) map2<std::uint32_t, std::uint32_t>(x, [](std::uint32_t a, std::uint32_t b) { return a * b; });
        else map2<T, T>(x, [](T a, T b) { return a * b; });
      });
      break;
    case XOp::Div:
      arith(x, [&](auto z) {
        using T = decltype(z);
        if constexpr (std::is_same_v<T, std::int32_t>)
          map2<T, T>(x, [](T a, T b) { return b == 0 ? 0 : (b == -1 ? T(0u - std::uint32_t(a)) : a / b); });
        else if constexpr (std::is_integral_v<T>) map2<T, T>(x, [](T a, T b) { return b == 0 ? 0 : a / b; });
        else map2<T, T>(x, [](T a, T b) { return a / b; });
      });
      break;
    case XOp::Rem:  // sign of the dividend (C's %, fmod)
      arith(x, [&](auto z) {
        using T = decltype(z);
        if constexpr (std::is_same_v<T, std::int32_t>) map2<T, T>(x, [](T a, T b) { return (b == 0 || b == -1) ? 0 : a % b; });
        else if constexpr (std::is_integral_v<T>) map2<T, T>(x, [](T a, T b) { return b == 0 ? 0 : a % b; });
        else map2<T, T>(x, [](T a, T b) { return a - b * std::trunc(a / b); });
      });
      break;
    case XOp::Mod:  // sign of the divisor (GLSL mod: x - y * floor(x / y))
      arith(x, [&](auto z) {
        using T = decltype(z);
        if constexpr (std::is_same_v<T, std::int32_t>)
          map2<T, T>(x, [](T a, T b) {
            if (b == 0 || b == -1) return T(0);
            T r = a % b;
            return (r != 0 && ((r < 0) != (b < 0))) ? r + b : r;
          });
        else if constexpr (std::is_integral_v<T>) map2<T, T>(x, [](T a, T b) { return b == 0 ? 0 : a % b; });
        else map2<T, T>(x, [](T a, T b) { return a - b * std::floor(a / b); });
      });
      break;
    case XOp::Shl: map2<std::uint32_t, std::uint32_t>(x, [](std::uint32_t a, std::uint32_t b) { return a << (b & 31u); }); break;
    case XOp::Shr: map2<std::uint32_t, std::uint32_t>(x, [](std::uint32_t a, std::uint32_t b) { return a >> (b & 31u); }); break;
    case XOp::Sar: map2<std::int32_t, std::int32_t>(x, [](std::int32_t a, std::int32_t b) { return a >> (b & 31); }); break;
    case XOp::And: case XOp::LogicalAnd: map2<std::uint32_t, std::uint32_t>(x, [](std::uint32_t a, std::uint32_t b) { return a & b; }); break;
    case XOp::Or: case XOp::LogicalOr: map2<std::uint32_t, std::uint32_t>(x, [](std::uint32_t a, std::uint32_t b) { return a | b; }); break;
    case XOp::Xor: case XOp::LogicalNe: map2<std::uint32_t, std::uint32_t>(x, [](std::uint32_t a, std::uint32_t b) { return a ^ b; }); break;
    case XOp::LogicalEq: map2<std::uint32_t, std::uint32_t>(x, [](std::uint32_t a, std::uint32_t b) { return std::uint32_t(a == b); }); break;
    case XOp::OrdEq: case XOp::OrdNe: case XOp::OrdLt: case XOp::OrdGt: case XOp::OrdLe: case XOp::OrdGe:
    case XOp::UnordEq: case XOp::UnordNe: case XOp::UnordLt: case XOp::UnordGt: case XOp::UnordLe:
    case XOp::UnordGe: case XOp::IEq: case XOp::INe: case XOp::SLt: case XOp::SGt: case XOp::SLe:
    case XOp::SGe: case XOp::ULt: case XOp::UGt: case XOp::ULe: case XOp::UGe:
      compare(x);
      break;
    case XOp::Select:
      if (x.s == Scalar::None) {  // one condition, whole value (a double's lanes span two rows)
        const std::uint32_t* cond = A + std::size_t(x.a) * L;
        const std::vector<std::uint32_t>* doubles = doubles_of(x.doubles);
        std::size_t k = 0;
        for (std::uint32_t w = 0; w < x.n;) {
          if (doubles && k < doubles->size() && (*doubles)[k] == w) {
            const double* t = row<double>(x.b + w);
            const double* f = row<double>(x.c + w);
            put(row<double>(x.dst + w), [&](int l) { return cond[l] ? t[l] : f[l]; });
            ++k;
            w += 2;
            continue;
          }
          const std::uint32_t* t = A + std::size_t(x.b + w) * L;
          const std::uint32_t* f = A + std::size_t(x.c + w) * L;
          put(A + std::size_t(x.dst + w) * L, [&](int l) { return cond[l] ? t[l] : f[l]; });
          ++w;
        }
      } else {  // per component
        for (std::uint32_t c = 0; c < x.n; ++c) {
          const std::uint32_t* cond = A + std::size_t(x.a + c) * L;
          if (x.s == Scalar::F64) {
            const double* t = row<double>(x.b, c);
            const double* f = row<double>(x.c, c);
            put(row<double>(x.dst, c), [&](int l) { return cond[l] ? t[l] : f[l]; });
          } else {
            const std::uint32_t* t = A + std::size_t(x.b + c) * L;
            const std::uint32_t* f = A + std::size_t(x.c + c) * L;
            put(A + std::size_t(x.dst + c) * L, [&](int l) { return cond[l] ? t[l] : f[l]; });
          }
        }
      }
      break;
    case XOp::IsNan: case XOp::IsInf:
      for (std::uint32_t c = 0; c < x.n; ++c) {
        std::uint32_t* d = A + std::size_t(x.dst + c) * L;
        const bool nan = x.op == XOp::IsNan;
        if (x.s == Scalar::F64) {
          const double* a = row<double>(x.a, c);
          put(d, [&](int l) { return std::uint32_t(nan ? std::isnan(a[l]) : std::isinf(a[l])); });
        } else {
          const float* a = row<float>(x.a, c);
          put(d, [&](int l) { return std::uint32_t(nan ? std::isnan(a[l]) : std::isinf(a[l])); });
        }
      }
      break;
    case XOp::Any: case XOp::All: {
      const bool any = x.op == XOp::Any;
      put(A + std::size_t(x.dst) * L, [&](int l) {
        std::uint32_t r = any ? 0u : 1u;
        for (std::uint32_t c = 0; c < x.m; ++c) {
          const std::uint32_t v = A[std::size_t(x.a + c) * L + l];
          r = any ? (r | v) : (r & v);
        }
        return r;
      });
      break;
    }
    case XOp::ConvFToS:
      if (x.s == Scalar::F64) map1<double, std::int32_t>(x, [](double a) { return to_int(a); });
      else map1<float, std::int32_t>(x, [](float a) { return to_int(a); });
      break;
    case XOp::ConvFToU:
      if (x.s == Scalar::F64) map1<double, std::uint32_t>(x, [](double a) { return to_uint(a); });
      else map1<float, std::uint32_t>(x, [](float a) { return to_uint(a); });
      break;
    case XOp::ConvSToF: case XOp::ConvUToF: {
      const bool sign = x.op == XOp::ConvSToF;
      // x.s is the operand's scalar; aux = 1 when the result is double.
      if (x.aux == 1) {
        if (sign) map1<std::int32_t, double>(x, [](std::int32_t a) { return double(a); });
        else map1<std::uint32_t, double>(x, [](std::uint32_t a) { return double(a); });
      } else {
        if (sign) map1<std::int32_t, float>(x, [](std::int32_t a) { return float(a); });
        else map1<std::uint32_t, float>(x, [](std::uint32_t a) { return float(a); });
      }
      break;
    }
    case XOp::FConvert:
      if (x.s == Scalar::F64) map1<double, float>(x, [](double a) { return float(a); });
      else map1<float, double>(x, [](float a) { return double(a); });
      break;
    case XOp::Bitcast:
      // Same words, but a double's rows are interleaved lane by lane: regroup when widths differ.
      if (x.aux == 0) {  // same widths: a copy
        words_copy(x.dst, x.a, x.n * std::uint32_t(scalar_words(x.s)), x.doubles);
      } else if (x.s == Scalar::F64) {  // double(s) -> 2n words
        for (std::uint32_t c = 0; c < x.m; ++c) {
          const std::uint32_t* s = A + std::size_t(x.a + 2 * c) * L;
          for (int half = 0; half < 2; ++half)
            put(A + std::size_t(x.dst + 2 * c + half) * L, [&](int l) { return s[2 * l + half]; });
        }
      } else {  // 2n words -> double(s)
        for (std::uint32_t c = 0; c < x.m / 2; ++c) {
          const std::uint32_t* lo = A + std::size_t(x.a + 2 * c) * L;
          const std::uint32_t* hi = A + std::size_t(x.a + 2 * c + 1) * L;
          put(row<double>(x.dst, c), [&](int l) {
            const std::uint64_t bits = std::uint64_t(lo[l]) | (std::uint64_t(hi[l]) << 32);
            return std::bit_cast<double>(bits);
          });
        }
      }
      break;
    case XOp::Dot: {
      auto go = [&](auto z) {
        using T = decltype(z);
        put(row<T>(x.dst, 0), [&](int l) {
          T s = row<T>(x.a, 0)[l] * row<T>(x.b, 0)[l];
          for (std::uint32_t c = 1; c < x.m; ++c) s = s + row<T>(x.a, c)[l] * row<T>(x.b, c)[l];
          return s;
        });
      };
      if (x.s == Scalar::F64) go(double{});
      else go(float{});
      break;
    }
    case XOp::VecTimesScalar: case XOp::MatTimesScalar:
      if (x.s == Scalar::F64) map2<double, double>(x, [](double a, double b) { return a * b; }, true);
      else map2<float, float>(x, [](float a, float b) { return a * b; }, true);
      break;
    case XOp::VecTimesMat: case XOp::MatTimesVec: case XOp::MatTimesMat: case XOp::OuterProduct:
    case XOp::Transpose:
      matrix(x);
      break;
    case XOp::Composite:
      for (const WordCopy& c : p.copies[x.aux])
        copy_rows(A + std::size_t(x.dst + c.dst_word) * L, A + std::size_t(c.src + c.src_word) * L, c.words,
                  doubles_of(c.doubles));
      break;
    case XOp::ExtractDyn: case XOp::InsertDyn: {
      const bool insert = x.op == XOp::InsertDyn;
      const std::uint32_t* index = A + std::size_t(insert ? x.c : x.b) * L;
      const bool is_signed = Scalar(x.aux) == Scalar::I32;
      auto clamp_index = [&](int l) {
        std::int64_t k = is_signed ? std::int64_t(std::int32_t(index[l])) : std::int64_t(index[l]);
        return std::uint32_t(std::clamp<std::int64_t>(k, 0, x.m - 1));
      };
      const std::uint32_t w = std::uint32_t(scalar_words(x.s));
      if (!insert) {
        if (w == 2) {
          put(row<double>(x.dst), [&](int l) { return row<double>(x.a, clamp_index(l))[l]; });
        } else {
          put(A + std::size_t(x.dst) * L, [&](int l) { return A[std::size_t(x.a + clamp_index(l)) * L + l]; });
        }
      } else {
        words_copy(x.dst, x.a, x.m * w, x.doubles);
        if (w == 2) {
          const double* v = row<double>(x.b);
          for (int l = 0; l < n; ++l)
            if (mask[l]) row<double>(x.dst, clamp_index(l))[l] = v[l];
        } else {
          const std::uint32_t* v = A + std::size_t(x.b) * L;
          for (int l = 0; l < n; ++l)
            if (mask[l]) A[std::size_t(x.dst + clamp_index(l)) * L + l] = v[l];
        }
      }
      break;
    }
    case XOp::Load: load(x); break;
    case XOp::Store: store(x); break;
    case XOp::AccessChain: access_chain(x); break;
    case XOp::CopyMemory: {
      XIns ld = x;
      ld.aux = x.b;
      load(ld);
      XIns st = x;
      st.a = x.dst;
      store(st);
      break;
    }
    case XOp::Ext: ext(x); break;
    case XOp::BitCount: map1<std::uint32_t, std::uint32_t>(x, [](std::uint32_t a) { return std::uint32_t(std::popcount(a)); }); break;
    case XOp::BitReverse:
      map1<std::uint32_t, std::uint32_t>(x, [](std::uint32_t a) {
        std::uint32_t r = 0;
        for (int i = 0; i < 32; ++i) r |= ((a >> i) & 1u) << (31 - i);
        return r;
      });
      break;
    case XOp::BitFieldInsert:
      for (std::uint32_t c = 0; c < x.n; ++c) {
        const std::uint32_t* base = A + std::size_t(x.a + c) * L;
        const std::uint32_t* ins = A + std::size_t(x.b + c) * L;
        const std::uint32_t* off = A + std::size_t(x.c) * L;
        const std::uint32_t* cnt = A + std::size_t(x.d) * L;
        put(A + std::size_t(x.dst + c) * L, [&](int l) {
          const std::uint32_t o = off[l] & 31u, k = std::min(cnt[l], 32u - o);
          const std::uint32_t mask_bits = k >= 32 ? 0xffffffffu : ((1u << k) - 1u) << o;
          return (base[l] & ~mask_bits) | ((ins[l] << o) & mask_bits);
        });
      }
      break;
    case XOp::BitFieldSExtract: case XOp::BitFieldUExtract:
      for (std::uint32_t c = 0; c < x.n; ++c) {
        const std::uint32_t* base = A + std::size_t(x.a + c) * L;
        const std::uint32_t* off = A + std::size_t(x.b) * L;
        const std::uint32_t* cnt = A + std::size_t(x.c) * L;
        const bool sign = x.op == XOp::BitFieldSExtract;
        put(A + std::size_t(x.dst + c) * L, [&](int l) {
          const std::uint32_t o = off[l] & 31u, k = std::min(cnt[l], 32u - o);
          if (k == 0) return 0u;
          std::uint32_t v = base[l] >> o;
          if (k < 32) {
            v &= (1u << k) - 1u;
            if (sign && (v >> (k - 1)) & 1u) v |= ~((1u << k) - 1u);
          }
          return v;
        });
      }
      break;
    case XOp::DPdx: case XOp::DPdy: case XOp::Fwidth:
      derivative(x);
      break;
    case XOp::Texture: texture(x); break;
    case XOp::AtomicInc: case XOp::AtomicDec: case XOp::AtomicLoad: case XOp::AtomicAdd:
    case XOp::AtomicSub: case XOp::AtomicStore: case XOp::AtomicSMin: case XOp::AtomicUMin:
    case XOp::AtomicSMax: case XOp::AtomicUMax: case XOp::AtomicAnd: case XOp::AtomicOr:
    case XOp::AtomicXor: case XOp::AtomicExchange: case XOp::AtomicCompareExchange:
      atomic(x);
      break;
    case XOp::Kill:
      for (int l = 0; l < n; ++l)
        if (mask[l]) inv.killed_[l] = 1;
      break;
    case XOp::Emit:
      // Lane by lane in increasing order: each lane's vertices stay in its own emission order.
      if (inv.emit_)
        for (int l = 0; l < n; ++l)
          if (mask[l]) inv.emit_(l, int(x.aux), x.b != 0);
      break;
  }
}

void Runner::run_block(const XBlock& b) {
  if (trace || source) return traced_block(b);  // once per block: the untraced loop stays as it was
  if (!b.phis.empty()) run_phis(b);
  const XIns* code = p.code.data() + b.first;
  for (std::uint32_t i = 0; i < b.count; ++i) exec(code[i]);
}

// Phis are parallel copies: every incoming value is read (into the staging rows) before any phi
// is written. When all active lanes came from the same block (the common case), whole rows move.
void Runner::run_phis(const XBlock& b) {
  std::uint32_t from = uniform_prev;
  if (!b.phis_overlap) {
    // No phi reads another's rows: when every active lane came from one block, each phi copies
    // straight from its incoming value, with no staging.
    bool same = true;
    if (from == kNone) {
      for (int l = 0; l < n && same; ++l)
        if (mask[l]) {
          if (from == kNone) from = prev[l];
          else same = prev[l] == from;
        }
    }
    if (same && from != kNone) {
      std::vector<std::uint32_t>& doubles = inv.phi_doubles_;
      for (const Phi& phi : b.phis) {
        std::uint32_t src = kNone;
        for (const auto& [value, pred] : phi.incoming)
          if (pred == from) src = value;
        if (src == kNone) fail("internal: phi without an incoming value for its predecessor", 0, 0);
        doubles.clear();
        for (const FlatComponent& c : phi.flat)
          if (c.scalar == Scalar::F64) doubles.push_back(c.word);
        copy_rows(A + std::size_t(phi.dst) * L, A + std::size_t(src) * L, phi.words,
                  doubles.empty() ? nullptr : &doubles);
      }
      return;
    }
    from = uniform_prev;
  }
  bool same = true;
  for (int l = 0; l < n && same && uniform_prev == kNone; ++l)
    if (mask[l]) {
      if (from == kNone) from = prev[l];
      else same = prev[l] == from;
    }
  std::uint32_t* staging = inv.staging_.data();
  std::size_t at = 0;
  for (const Phi& phi : b.phis) {
    for (int l = 0; l < n; ++l) {
      if (!mask[l]) continue;
      const std::uint32_t came_from = uniform_prev != kNone ? uniform_prev : prev[l];
      std::uint32_t src = kNone;
      for (const auto& [value, pred] : phi.incoming)
        if (pred == came_from) src = value;
      if (src == kNone) fail("internal: phi without an incoming value for its predecessor", l, 0);
      if (same) {  // every active lane reads the same row: copy the whole rows
        std::copy_n(A + std::size_t(src) * L, std::size_t(phi.words) * L, staging + at);
        break;
      }
      for (const FlatComponent& c : phi.flat) {
        const int w = scalar_words(c.scalar);
        const std::uint32_t* s = A + std::size_t(src + c.word) * L + std::size_t(l) * w;
        std::uint32_t* d = staging + at + std::size_t(c.word) * L + std::size_t(l) * w;
        d[0] = s[0];
        if (w == 2) d[1] = s[1];
      }
    }
    at += std::size_t(phi.words) * L;
  }
  at = 0;
  std::vector<std::uint32_t>& doubles = inv.phi_doubles_;
  for (const Phi& phi : b.phis) {
    doubles.clear();
    for (const FlatComponent& c : phi.flat)
      if (c.scalar == Scalar::F64) doubles.push_back(c.word);
    copy_rows(A + std::size_t(phi.dst) * L, staging + at, phi.words, doubles.empty() ? nullptr : &doubles);
    at += std::size_t(phi.words) * L;
  }
}

Invocations::Invocations(const Executable& exe) : exe_(exe) {
  const DecodedProgram& p = *exe.program_;
  arena_.assign(std::size_t(p.arena_rows) * kMaxLanes, 0u);
  shared_.assign(p.shared_words + std::size_t(kMaxLanes) * p.group_words, 0u);
  for (std::uint32_t& g : group_base_) g = p.shared_words;
  killed_.assign(kMaxLanes, 0);
  storage_.assign(p.slots.size(), nullptr);
  std::size_t phi_words = 0;
  for (const XBlock& b : p.blocks) {
    std::size_t words = 0;
    for (const Phi& phi : b.phis) words += phi.words;
    phi_words = std::max(phi_words, words);
  }
  staging_.assign(phi_words * kMaxLanes, 0u);
  // Constants: the same value in every lane, set once.
  for (const auto& [row, words] : p.constant_init) {
    for (std::uint32_t w = 0; w < words.size(); ++w) {
      std::uint32_t* r = arena_.data() + std::size_t(row + w) * kMaxLanes;
      std::fill(r, r + kMaxLanes, words[w]);
    }
  }
  // Double constants: rows hold kMaxLanes doubles, not a word per lane.
  for (const auto& [row, scalar] : p.constant_scalars) {
    if (scalar != Scalar::F64) continue;
    std::uint32_t* r = arena_.data() + std::size_t(row) * kMaxLanes;
    const std::uint32_t lo = r[0], hi = r[kMaxLanes];
    for (int l = 0; l < kMaxLanes; ++l) {
      r[2 * l] = lo;
      r[2 * l + 1] = hi;
    }
  }
  for (const auto& [slot, init] : p.shared_inits)
    std::copy(init.begin(), init.end(), shared_.begin() + p.slots[slot].base);
}

Invocations::~Invocations() = default;

std::uint32_t Invocations::group_word(int group) const {
  const DecodedProgram& p = *exe_.program_;
  return p.shared_words + std::uint32_t(group) * p.group_words;
}

void Invocations::zero_shared(int groups) {
  const DecodedProgram& p = *exe_.program_;
  const std::size_t used = p.shared_words + std::size_t(std::clamp(groups, 1, kMaxLanes)) * p.group_words;
  std::fill(shared_.begin(), shared_.begin() + std::ptrdiff_t(used), 0u);
}

void Invocations::set_group(int lane, int group) { group_base_[lane] = group_word(group); }

void Invocations::bind_storage(std::uint32_t variable_id, std::uint32_t* words) {
  const DecodedProgram& p = *exe_.program_;
  if (variable_id < p.slot_of_id.size() && p.slot_of_id[variable_id] != kNone)
    storage_[p.slot_of_id[variable_id]] = words;
}

void Invocations::bind_image(std::uint32_t unit, texture::Texture* t) {
  if (images_.size() <= unit) images_.resize(unit + 1, nullptr);
  images_[unit] = t;
}

void Invocations::set_helpers(const std::uint8_t* helper) {
  std::copy_n(helper, lanes_, helper_);
  has_helpers_ = true;
}

void Invocations::bind_texture(std::uint32_t binding, const texture::Texture* t) {
  if (textures_.size() <= binding) textures_.resize(binding + 1, nullptr);
  textures_[binding] = t;
}

void Invocations::set_sampling_vectors(const std::uint32_t* keys) {
  std::copy_n(keys, lanes_, sampling_vector_);
  has_sampling_vectors_ = true;
}

void Invocations::begin(int lanes, int groups) {
  has_sampling_vectors_ = false;
  if (has_helpers_) std::fill_n(helper_, kMaxLanes, std::uint8_t(0));
  has_helpers_ = false;
  lanes_ = std::clamp(lanes, 0, kMaxLanes);
  groups_ = std::clamp(groups, 1, kMaxLanes);
  const std::uint32_t first = group_word(0);
  for (std::uint32_t& g : group_base_) g = first;
  const DecodedProgram& p = *exe_.program_;
  const Module& m = exe_.module();
  std::fill_n(killed_.begin(), lanes_, 0);
  for (const auto& [slot, init] : p.lane_resets) {
    const VariableSlot& v = p.slots[slot];
    std::uint32_t* base = arena_.data() + std::size_t(v.base) * kMaxLanes;
    if (init.empty()) {
      // Only the running lanes' words: min(2n, L) words of each row cover n lanes of a 32-bit row
      // and of both rows of a double (whose lane l is at words 2l and 2l + 1 of the two).
      const std::size_t words = std::size_t(std::min(2 * lanes_, kMaxLanes));
      for (std::uint32_t w = 0; w < v.words; ++w)
        std::fill_n(base + std::size_t(w) * kMaxLanes, words, 0u);
      continue;
    }
    const Type& t = m.type(m.variable(v.id)->type);
    for (const FlatComponent& c : t.flat) {
      std::uint32_t* r = base + std::size_t(c.word) * kMaxLanes;
      for (int l = 0; l < kMaxLanes; ++l) {
        if (c.scalar == Scalar::F64) {
          r[2 * l] = init[c.word];
          r[2 * l + 1] = init[c.word + 1];
        } else {
          r[l] = init[c.word];
        }
      }
    }
  }
}

namespace {

// The block a lane goes to after terminator t; kNone when it stops (return, discard).
std::uint32_t successor(const Terminator& t, const std::uint32_t* arena, int lane) {
  const std::uint32_t value = t.reg == kNone ? 0u : arena[std::size_t(t.reg) * kMaxLanes + lane];
  switch (t.kind) {
    case TermKind::Branch: return t.target;
    case TermKind::Cond: return value ? t.target : t.other;
    case TermKind::Switch: {
      std::uint32_t to = t.other;
      for (const auto& [literal, target] : t.cases)
        if (literal == value) to = target;
      return to;
    }
    default: return kNone;
  }
}

}  // namespace

void Invocations::run() {
  const DecodedProgram& p = *exe_.program_;
  Runner r{.inv = *this, .p = p, .A = arena_.data(), .n = lanes_};  // the rest value-initialized
  r.trace = current_nan_trace();  // once per batch
  if (r.trace && (r.trace->lane >= lanes_ || r.trace->found)) r.trace = nullptr;
  r.source = current_source_trace();
  if (r.source && r.source->lane >= lanes_) r.source = nullptr;
  const std::uint64_t budget = exe_.limits().max_instructions;
  const std::string budget_message =
      "instruction budget of " + std::to_string(budget) +
      " exceeded (an infinite loop?); raise it with the scene key shaders.max_instructions "
      "(render, inspect: --set shaders.max_instructions=N) or shader-test's --max-shader-instructions";
  for (int l = 0; l < lanes_; ++l) {
    r.pc[l] = 0;
    r.prev[l] = kNone;
    r.steps[l] = 0;
    r.mask[l] = 1;
  }
  for (int l = 0; l < lanes_;) {  // the groups' runs of lanes
    int end = l + 1;
    while (end < lanes_ && group_base_[end] == group_base_[l]) ++end;
    r.group_runs[r.num_group_runs++] = {l, end};
    l = end;
  }
  // A lane's instruction count is common (counted once while the lanes run together) plus its
  // own steps (counted per lane while they diverge).
  std::uint64_t common = 0, most_steps = 0;
  auto over_budget = [&](const Terminator& t) {
    for (int l = 0; l < lanes_; ++l)
      if (r.mask[l] && common + r.steps[l] > budget) r.fail(budget_message, l, t.line);
  };
  // Converged: every lane still running is at `block` (r.mask holds them), so nothing is scanned
  // per lane until a branch sends lanes different ways. r.uniform_prev: the block they all came
  // from (kNone right after they meet again, when each lane's prev[] says).
  bool converged = true;
  std::uint32_t block = 0;
  int running = lanes_;
  r.uniform_prev = kNone;
  while (running > 0) {
    if (converged) {
      r.full = running == lanes_;
      const XBlock& b = p.blocks[block];
      r.run_block(b);
      const Terminator& t = b.term;
      common += b.count + 1;
      if (common + most_steps > budget) over_budget(t);
      std::uint32_t to = kNone;
      bool uniform = true;
      switch (t.kind) {
        case TermKind::Branch: to = t.target; break;
        case TermKind::Return:
        case TermKind::Unreachable: running = 0; break;
        case TermKind::Kill:
          for (int l = 0; l < lanes_; ++l) killed_[l] |= r.mask[l];
          running = 0;
          break;
        case TermKind::Cond:
        case TermKind::Switch: {
          if (t.kind == TermKind::Cond && r.full) {  // all lanes one way? (reductions, vectorized)
            const std::uint32_t* c = arena_.data() + std::size_t(t.reg) * kMaxLanes;
            std::uint32_t any = 0, all = 1;
            for (int l = 0; l < lanes_; ++l) {
              any |= c[l];
              all &= c[l];
            }
            if (all || !any) {
              to = all ? t.target : t.other;
              break;
            }
          }
          for (int l = 0; l < lanes_; ++l) {
            if (!r.mask[l]) continue;
            const std::uint32_t lane_to = successor(t, arena_.data(), l);
            r.pc[l] = lane_to;
            if (to == kNone) to = lane_to;
            else uniform &= lane_to == to;
          }
          break;
        }
      }
      if (running == 0) break;
      if (uniform) {
        r.uniform_prev = block;
        block = to;
        continue;
      }
      for (int l = 0; l < lanes_; ++l)  // the lanes part: each at its own block from here
        if (r.mask[l]) r.prev[l] = block;
      converged = false;
      continue;
    }

    block = kNone;
    for (int l = 0; l < lanes_; ++l) block = std::min(block, r.pc[l]);
    int active = 0;
    for (int l = 0; l < lanes_; ++l) {
      r.mask[l] = r.pc[l] == block;
      active += r.mask[l];
    }
    r.full = active == lanes_;
    r.uniform_prev = kNone;
    const XBlock& b = p.blocks[block];
    r.run_block(b);
    const Terminator& t = b.term;
    std::uint32_t next = kNone;
    bool same = active == running;
    for (int l = 0; l < lanes_; ++l) {
      if (!r.mask[l]) continue;
      r.steps[l] += b.count + 1;
      most_steps = std::max(most_steps, r.steps[l]);
      if (common + r.steps[l] > budget) r.fail(budget_message, l, t.line);
      r.prev[l] = block;
      if (t.kind == TermKind::Kill) killed_[l] = 1;
      const std::uint32_t to = successor(t, arena_.data(), l);
      r.pc[l] = to;
      if (to == kNone) --running;
      else if (next == kNone) next = to;
      else same &= to == next;
    }
    if (same && running > 0) {  // every running lane meets at `next`: together again
      converged = true;
      block = next;
      for (int l = 0; l < lanes_; ++l) r.mask[l] = r.pc[l] == next;
    }
  }
}

namespace {
std::atomic<std::uint64_t> next_serial{1};

// Refuses a program whose invocations need more private memory than limits.max_private_bytes
// (arena rows are words per invocation), naming its largest per-invocation variable: the cause
// when the total is this large (a local array), where registers and constants are not.
void check_private_memory(const Module& m, const DecodedProgram& p, const ExecLimits& limits) {
  const std::uint64_t bytes = std::uint64_t(p.arena_rows) * 4;
  if (bytes <= limits.max_private_bytes) return;
  const VariableSlot* largest = nullptr;
  for (const VariableSlot& s : p.slots)
    if (s.per_lane && (!largest || s.words > largest->words)) largest = &s;
  std::string what = "an invocation needs " + std::to_string(bytes) + " bytes of private memory";
  if (largest) {
    const Variable* v = m.variable(largest->id);
    const std::string name = v && !v->name.empty() ? v->name : m.name_of(largest->id);
    what = "'" + name + "' takes " + std::to_string(std::uint64_t(largest->words) * 4) +
           " bytes per invocation (" + std::to_string(bytes) + " bytes in all)";
  }
  throw SpirvError(what + ", more than the executor's private memory limit of " +
                   std::to_string(limits.max_private_bytes) + " bytes per invocation (it keeps " +
                   std::to_string(kMaxLanes) + " invocations per thread)");
}
}  // namespace

Executable::Executable(Module module, ExecLimits limits)
    : module_(std::move(module)), limits_(limits), program_(decode_program(module_)),
      serial_(next_serial++) {
  check_private_memory(module_, *program_, limits_);
}

Invocations& Executable::local() const {
  struct Entry {
    std::weak_ptr<const bool> alive;
    std::unique_ptr<Invocations> invocations;
  };
  thread_local std::unordered_map<std::uint64_t, Entry> cache;
  if (const auto it = cache.find(serial_); it != cache.end()) return *it->second.invocations;
  // First use on this thread: drop the state of executables that are gone. Kept, every
  // program ever run held an arena on every thread that ran it, and a process that builds programs
  // again and again (piglit files, fuzz_pipeline's renders) grew without bound.
  std::erase_if(cache, [](const auto& e) { return e.second.alive.expired(); });
  Entry& e = cache[serial_];
  e.alive = alive_;
  e.invocations = std::make_unique<Invocations>(*this);
  return *e.invocations;
}

Executable::~Executable() = default;

bool Executable::may_discard() const {
  for (const XBlock& b : program_->blocks) {
    if (b.term.kind == TermKind::Kill) return true;
    for (std::uint32_t i = 0; i < b.count; ++i)
      if (program_->code[b.first + i].op == XOp::Kill) return true;
  }
  return false;
}

bool Executable::reads_quads() const {
  for (const XIns& x : program_->code) {
    if (x.op == XOp::DPdx || x.op == XOp::DPdy || x.op == XOp::Fwidth) return true;
    // An implicit LOD (texture() without Lod or Grad, textureQueryLod) differentiates too.
    if (x.op == XOp::Texture) {
      const TexOp& t = program_->textures[x.aux];
      if (t.implicit_lod || t.kind == TexOp::Kind::QueryLod) return true;
    }
  }
  return false;
}

bool Executable::writes_memory() const {
  for (const XIns& x : program_->code) {
    const bool store = x.op == XOp::Store || x.op == XOp::CopyMemory;
    const bool atomic = x.op >= XOp::AtomicInc && x.op <= XOp::AtomicCompareExchange && x.op != XOp::AtomicLoad;
    if (x.op == XOp::Texture) {
      const TexOp& t = program_->textures[x.aux];
      if (t.kind == TexOp::Kind::ImageWrite || (t.kind == TexOp::Kind::ImageAtomic && t.atomic != XOp::AtomicLoad))
        return true;
    }
    if (!store && !atomic) continue;
    const VariableSlot& v = program_->slots[program_->accesses[x.aux].slot];
    if (v.storage || (atomic && !v.per_lane)) return true;
  }
  return false;
}

bool Executable::samples_textures() const {
  for (const XIns& x : program_->code)
    if (x.op == XOp::Texture && program_->textures[x.aux].kind == TexOp::Kind::Sample) return true;
  return false;
}

const VariableSlot* Executable::slot(std::uint32_t id) const {
  if (id >= program_->slot_of_id.size() || program_->slot_of_id[id] == kNone) return nullptr;
  return &program_->slots[program_->slot_of_id[id]];
}

}  // namespace tessref::shader
