// common/deform/fast_deform.cpp — free-form deformation of many vertices at
// once (fast_deform.h): deform_mesh's results, computed in another order.
#include "deform/fast_deform.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "spline/basis.h"
#include "spline/fast/kernels.h"  // GLLAB_SPLINE_CLONES: the spline core's instruction-set clones

namespace gllab::deform {

// ==== what the fast layer does ============================================================
//
// deform_mesh (ffd.cpp) runs, per vertex: (s, t, u) = M^-1 (x - X0) and the
// box test; per direction A2.1 FindSpan and A2.3 DersBasisFuns; the sum of
// (p + 1)^3 control points with the value and the three derivative weights
// (sum factorisation); J = [Xs Xt Xu] M^-1, det J and cof(J) n. About 2 M
// vertices/s. Here the same quantities, in this order (bench/README.md,
// "ffd_bench", has what each step bought):
//
// 1. Taylor form per span. In one direction the clamped uniform knots have
//    `segments` spans; on span j every non-zero basis function N_{j+r} is a
//    polynomial of degree p. A2.3 DersBasisFuns at the span's centre c_j,
//    with all p derivatives, gives its Taylor coefficients N^(k)_{j+r}(c_j) /
//    k!, once per span and direction (axis_table): the fast layer is derived
//    from the book's algorithm, not from a second formula for the basis.
//    About the centre, not the left knot: on random Bernstein lattices of
//    degree 5 the power form about the left knot lost four digits (1.5e-11 of
//    the lattice's size), about the centre none (9e-16, as the textbook's
//    1e-15): |x - c| <= h / 2 keeps the monomials small.
// 2. One polynomial per cell. A cell is one span in each direction (the
//    Bernstein lattice, which has no interior knot, is one cell). On it
//    X(s, t, u) = sum_abc C_abc x^a y^b z^c, x = s - c_s, y = t - c_t,
//    z = u - c_u, with C_abc = sum_ijk P_ijk T^s_ia T^t_jb T^u_kc: the
//    window's (p + 1)^3 control points contracted with the three Taylor
//    tables, direction by direction (cell_coefficients). Computed once per
//    cell that holds a vertex and kept (CellCache).
// 3. Horner per vertex. X, Xs, Xt, Xu come from a nested Horner scheme: in u
//    the (p + 1)^2 polynomials of each component with their u-derivatives,
//    then in t, then in s. For p = 3: 123 multiplications and 123 additions
//    per component (369 + 369 in all), where the textbook's (p + 1)^3 sum
//    alone costs 576 + 576, and its A2.1 / A2.3 about 30 divisions.
// 4. The normal without J. cof is multiplicative, cof(J) = cof([Xs Xt Xu])
//    cof(M^-1), and cof(M^-1) = M^T / det M: the direction of cof(J) n is that
//    of cof([Xs Xt Xu]) (M^T n). The cofactor's first column Xt x Xu also
//    gives det [Xs Xt Xu] = Xs . (Xt x Xu), ffd.cpp's formula; det J = that /
//    det M as there. J itself is never formed.
// 5. Buckets. The vertices are taken in chunks (kChunk, so that the scratch
//    stays in L2), their (s, t, u), cells and M^T n computed component-wise
//    in loops without a branch (they vectorise). The span in each direction
//    is floor(w * segments); only where that is within 1e-9 of an integer do
//    the knots decide, as in A2.1 (cell_pass). The chunk is sorted by cell
//    (a counting sort; the outside vertices are a bucket of their own), and
//    each cell's bucket goes through the kernel in blocks of kBlock vertices
//    gathered component-wise (a copy when they are consecutive, as in the
//    Bernstein lattice's one cell).
// 6. The kernel. horner<P> works on 8 vertices at once (GCC's vector
//    extension: one AVX-512 register, two AVX2, four SSE2) and reads one
//    cell's coefficients; the degree is a template argument for P = 1..5, so
//    that its loops unroll ("#pragma GCC unroll") and the partial sums stay
//    in registers. A lattice whose degrees differ uses the kernel of its
//    largest degree with the other directions' coefficients zero-padded (the
//    Horner steps over a zero leading coefficient are exact). horner<0> is the
//    same code with the degree read at run time (degrees 6..kMaxFastDegree);
//    above kMaxFastDegree every vertex goes through the textbook evaluator
//    (fast_deform.h says why). det J and the normal (finish) are a plain loop
//    that the auto-vectoriser takes.
// 7. Instruction sets. The kernels and passes are GLLAB_SPLINE_CLONES
//    functions (target_clones: AVX-512, AVX2, baseline x86-64, picked at load
//    time). -ffp-contract=off (common/deform/CMakeLists.txt) and no
//    reassociation: every clone gives the same bits. This file also has
//    -fno-math-errno (std::sqrt vectorises; no result changes) and
//    -fschedule-insns -fsched-pressure (the Horner chains interleaved; the
//    same arithmetic).
//
// What is not changed: the local coordinates and the box test are Mapper::local's
// arithmetic (the same operations in the same order, with deform_mesh's slack
// for float vertices), so the inside / outside decision and the clamping are
// deform_mesh's bit for bit; outside vertices get deform_mesh's values exactly
// (x, deform_normal(I, n), det 1).

namespace {

constexpr int kQ = kMaxFastDegree + 1;     // Taylor coefficients per direction, at most
constexpr std::size_t kChunk = 4096;       // vertices sorted at a time
constexpr int kBlock = 128;                // vertices per kernel call
constexpr std::size_t kCacheDoubles = 1 << 19;  // 4 MB of cell coefficients at most

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}
std::string vec_text(Vec3 v) { return "(" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ")"; }

// ---- one direction: spans and their Taylor coefficients (step 1) ---------------------------

struct AxisTable {
  int p = 1, segments = 1;
  std::vector<double> lower, upper;  // span j is [lower[j], upper[j]); upper ends with +inf
  std::vector<double> centre;  // per span
  std::vector<double> taylor;  // per span, (p + 1)^2: [r (p + 1) + k] = N^(k)_{j+r}(c_j) / k!
};

AxisTable axis_table(const Volume& v, int axis) {
  AxisTable a;
  a.p = v.degree[axis];
  a.segments = v.count[axis] - a.p;
  const std::vector<double> U = volume_knots(v, axis);
  const int q = a.p + 1;
  a.lower.assign(U.begin() + a.p, U.begin() + a.p + a.segments);
  a.upper.assign(U.begin() + a.p + 1, U.begin() + a.p + a.segments + 1);
  a.upper.back() = INFINITY;  // the last span holds w = 1 too (A2.1's special case)
  a.centre.resize(a.segments);
  a.taylor.resize(std::size_t(a.segments) * q * q);
  double ders[kQ * kQ];
  for (int j = 0; j < a.segments; ++j) {
    const int span = a.p + j;
    const double c = (U[span] + U[span + 1]) / 2;
    a.centre[j] = c;
    spline::ders_basis_funs(span, c, a.p, a.p, U, ders);  // A2.3 with all p derivatives
    double factorial = 1;
    for (int k = 0; k <= a.p; ++k) {
      if (k > 0) factorial *= k;
      for (int r = 0; r <= a.p; ++r)
        a.taylor[(std::size_t(j) * q + r) * q + k] = ders[k * q + r] / factorial;
    }
  }
  return a;
}

// ---- the lattice, prepared once ---------------------------------------------------------

struct Setup {
  Vec3 origin;
  Mat3 m, m_inv;  // M = [S T U] and its inverse, as ffd.cpp's Mapper has it
  double det_m = 1;
  int degree = 1;       // the largest of the three: the kernel's
  bool fast = true;     // degree <= kMaxFastDegree
  AxisTable axis[3];
  std::size_t cells = 1;  // segments_s * segments_t * segments_u
  const Volume* volume = nullptr;

  explicit Setup(const Lattice& l)
      : origin(l.frame.origin), m(l.frame.matrix()), volume(&l.volume) {
    // deform_mesh's order: the volume (VolumeEvaluator validates it), then
    // the frame (ffd.cpp's frame_det, the same message).
    validate(l.volume);
    det_m = det(m);
    const bool finite_origin =
        std::isfinite(origin.x) && std::isfinite(origin.y) && std::isfinite(origin.z);
    if (!(det_m > 0) || !finite_origin)
      throw std::invalid_argument("lattice frame: det [S T U] = " + num(det_m) +
                                  " (the box must have volume and S, T, U be right-handed)");
    m_inv = inverse(m);
    degree = std::max({l.volume.degree[0], l.volume.degree[1], l.volume.degree[2]});
    fast = degree <= kMaxFastDegree;
    if (!fast) return;  // the textbook evaluator; one bucket
    for (int a = 0; a < 3; ++a) axis[a] = axis_table(l.volume, a);
    cells = std::size_t(axis[0].segments) * axis[1].segments * axis[2].segments;
  }
  std::size_t coefficient_count() const {
    const std::size_t q = std::size_t(degree) + 1;
    return 3 * q * q * q;
  }
};

// ---- one cell's polynomial (step 2) ----------------------------------------------------------

/// C[((m Q + a) Q + b) Q + c], Q = degree + 1 (the kernel's), for component m
/// of X: the coefficient of x^a y^b z^c about the cell's centre; zero where a,
/// b or c exceeds that direction's own degree.
void cell_coefficients(const Setup& st, int js, int jt, int ju, double* C) {
  const Volume& v = *st.volume;
  const int Q = st.degree + 1;
  const int qs = st.axis[0].p + 1, qt = st.axis[1].p + 1, qu = st.axis[2].p + 1;
  const double* Ts = &st.axis[0].taylor[std::size_t(js) * qs * qs];
  const double* Tt = &st.axis[1].taylor[std::size_t(jt) * qt * qt];
  const double* Tu = &st.axis[2].taylor[std::size_t(ju) * qu * qu];
  std::fill(C, C + st.coefficient_count(), 0.0);
  double A[kQ][kQ][kQ], B[kQ][kQ][kQ];
  for (int m = 0; m < 3; ++m) {
    // A[i][j][c] = sum_k P_ijk T^u_kc; the window of span (js, jt, ju) starts
    // at control point (js, jt, ju).
    for (int i = 0; i < qs; ++i)
      for (int j = 0; j < qt; ++j) {
        const Vec3* row = &v.point(js + i, jt + j, ju);
        for (int c = 0; c < qu; ++c) {
          double acc = 0;
          for (int k = 0; k < qu; ++k) {
            const double pk = m == 0 ? row[k].x : m == 1 ? row[k].y : row[k].z;
            acc += pk * Tu[k * qu + c];
          }
          A[i][j][c] = acc;
        }
      }
    // B[i][b][c] = sum_j A[i][j][c] T^t_jb
    for (int i = 0; i < qs; ++i)
      for (int b = 0; b < qt; ++b)
        for (int c = 0; c < qu; ++c) {
          double acc = 0;
          for (int j = 0; j < qt; ++j) acc += A[i][j][c] * Tt[j * qt + b];
          B[i][b][c] = acc;
        }
    // C[a][b][c] = sum_i B[i][b][c] T^s_ia
    for (int a = 0; a < qs; ++a)
      for (int b = 0; b < qt; ++b)
        for (int c = 0; c < qu; ++c) {
          double acc = 0;
          for (int i = 0; i < qs; ++i) acc += B[i][b][c] * Ts[i * qs + a];
          C[((std::size_t(m) * Q + a) * Q + b) * Q + c] = acc;
        }
  }
}

/// The coefficients of the cells that hold vertices, computed on first use.
/// When kCacheDoubles would be exceeded (lattices of many cells), the cache
/// starts over; the coefficients are a function of the cell alone, so the
/// results do not depend on it.
class CellCache {
 public:
  explicit CellCache(const Setup& st) : st_(st), per_cell_(st.coefficient_count()) {
    if (st.fast) slot_.assign(st.cells, -1);
    capacity_ = std::max<std::size_t>(1, kCacheDoubles / per_cell_);
  }
  /// Valid until the next call.
  const double* get(std::size_t cell) {
    if (slot_[cell] < 0) {
      if (cached_.size() == capacity_) {
        for (std::size_t c : cached_) slot_[c] = -1;
        cached_.clear();
      }
      slot_[cell] = int(cached_.size());
      cached_.push_back(cell);
      if (data_.size() < cached_.size() * per_cell_) data_.resize(cached_.size() * per_cell_);
      const std::size_t su = std::size_t(st_.axis[2].segments);
      const std::size_t st = std::size_t(st_.axis[1].segments);
      cell_coefficients(st_, int(cell / (st * su)), int(cell / su % st), int(cell % su),
                        &data_[std::size_t(slot_[cell]) * per_cell_]);
    }
    return &data_[std::size_t(slot_[cell]) * per_cell_];
  }

 private:
  const Setup& st_;
  std::size_t per_cell_, capacity_;
  std::vector<int> slot_;
  std::vector<std::size_t> cached_;
  std::vector<double> data_;
};

// ---- the chunk: its vertices component-wise (step 5) -----------------------------------------

/// The scratch of one chunk of at most kChunk vertices, component-wise; in L2.
struct Chunk {
  // in: (s, t, u) clamped onto the box (0 outside), M^T n (when there are normals)
  std::vector<double> s, t, u, nx, ny, nz;
  // out: X(s, t, u), the unit normal, det J
  std::vector<double> X, Y, Z, Nx, Ny, Nz, det;
  std::vector<std::uint32_t> cell;    // the cell, or Setup::cells for outside
  std::vector<std::uint32_t> order;   // chunk indices sorted by cell
  std::vector<std::uint32_t> counts;  // the counting sort's
  std::vector<std::uint8_t> near;     // 1: cell_pass's span must be checked
  Chunk()
      : s(kChunk), t(kChunk), u(kChunk), nx(kChunk), ny(kChunk), nz(kChunk), X(kChunk),
        Y(kChunk), Z(kChunk), Nx(kChunk), Ny(kChunk), Nz(kChunk), det(kChunk), cell(kChunk),
        order(kChunk), near(kChunk) {}
};

/// kBlock vertices of one cell gathered from a chunk, component-wise. The
/// kernel works on whole groups of 8: lanes past the count hold earlier
/// vertices' values (finite; value-initialised at first) and are not read back.
struct Block {
  double s[kBlock], t[kBlock], u[kBlock], nx[kBlock], ny[kBlock], nz[kBlock];
  double X[3][kBlock];  // X(s, t, u) by component
  double D[9][kBlock];  // Xs, Xt, Xu by component
  double Nx[kBlock], Ny[kBlock], Nz[kBlock], det[kBlock];
};

/// The cell's centre (c_s, c_t, c_u), its coefficients (cell_coefficients)
/// and the kernel's degree.
struct CellData {
  const double* C;
  int degree;
  double cs, ct, cu, det_m;
};

// ---- the kernel (steps 3, 4, 6) --------------------------------------------------------------

/// 8 doubles: 8 vertices at once (GCC's vector extension; an AVX-512
/// register, two AVX2 or four SSE2 registers, by clone).
typedef double V8 __attribute__((vector_size(64)));
constexpr int kLanes = 8;
static_assert(kBlock % kLanes == 0, "whole groups of 8 in a block");

/// X, Xs, Xt, Xu for the first `groups` groups of 8 of b (b.s, b.t, b.u)
/// from the cell's coefficients: the nested Horner scheme (step 3). Pt = 0:
/// the degree cd.degree read at run time.
///
/// Written with 8-vertex vectors rather than left to the auto-vectoriser:
/// that one hoists the (p + 1)^3 * 3 coefficient broadcasts out of the loop,
/// which cannot keep 192 of them in 32 registers and spills them (433 stack
/// accesses per 8 vertices at p = 3). Here the coefficient pointer is made
/// opaque in each iteration (the empty asm), so each coefficient is read
/// where it is used, as a broadcast operand of the add (AVX-512's {1to8}).
template <int Pt>
[[gnu::always_inline]] inline void horner(const CellData& cd, int groups, Block& b) {
  constexpr int kN = Pt > 0 ? Pt + 1 : kQ;  // array sizes
  const int P = Pt > 0 ? Pt : std::clamp(cd.degree, 1, kMaxFastDegree);
  const int Q = P + 1;
  for (int g = 0; g < groups; ++g) {
    const double* C = cd.C;
    asm("" : "+r"(C));  // not loop-invariant as far as the compiler knows: see above
    V8 x, y, z;
    std::memcpy(&x, b.s + kLanes * g, sizeof x);
    std::memcpy(&y, b.t + kLanes * g, sizeof y);
    std::memcpy(&z, b.u + kLanes * g, sizeof z);
    x -= cd.cs, y -= cd.ct, z -= cd.cu;
    const int at = kLanes * g;
    // Component by component, as a loop: unrolled, the three would triple the
    // code (and the compile time, which is then a minute per instruction set)
    // for no measured gain.
#pragma GCC unroll 1
    for (int m = 0; m < 3; ++m) {
      V8 W[kN] = {}, Wt[kN] = {}, Wu[kN] = {};  // per power of x: the value, d/dt, d/du
#pragma GCC unroll 9
      for (int a = 0; a <= P; ++a) {
        V8 V[kN] = {}, D[kN] = {};  // per power of y: the value and d/du
#pragma GCC unroll 9
        for (int e = 0; e <= P; ++e) {
          // Horner in z with the derivative alongside (d before val).
          const double* c = C + ((m * Q + a) * Q + e) * Q;
          V8 d = V8{} + c[P], val = c[P] * z + c[P - 1];
#pragma GCC unroll 9
          for (int k = P - 2; k >= 0; --k) {
            d = d * z + val;
            val = val * z + c[k];
          }
          V[e] = val, D[e] = d;
        }
        V8 w = V[P] * y + V[P - 1], wt = V[P], wu = D[P] * y + D[P - 1];
#pragma GCC unroll 9
        for (int k = P - 2; k >= 0; --k) {
          wt = wt * y + w;
          w = w * y + V[k];
          wu = wu * y + D[k];
        }
        W[a] = w, Wt[a] = wt, Wu[a] = wu;
      }
      V8 val = W[P] * x + W[P - 1], ds = W[P];
      V8 dt = Wt[P] * x + Wt[P - 1], du = Wu[P] * x + Wu[P - 1];
#pragma GCC unroll 9
      for (int k = P - 2; k >= 0; --k) {
        ds = ds * x + val;
        val = val * x + W[k];
        dt = dt * x + Wt[k];
        du = du * x + Wu[k];
      }
      std::memcpy(b.X[m] + at, &val, sizeof(V8));
      std::memcpy(b.D[m] + at, &ds, sizeof(V8));
      std::memcpy(b.D[3 + m] + at, &dt, sizeof(V8));
      std::memcpy(b.D[6 + m] + at, &du, sizeof(V8));
    }
  }
}

/// det J and the unit normal from Xs, Xt, Xu (step 4), for `count` vertices
/// of b. A plain loop: the auto-vectoriser does it.
template <bool Normals>
[[gnu::always_inline]] inline void finish(int count, double det_m, Block& __restrict b) {
  for (int v = 0; v < count; ++v) {
    const Vec3 Xs{b.D[0][v], b.D[1][v], b.D[2][v]}, Xt{b.D[3][v], b.D[4][v], b.D[5][v]};
    const Vec3 Xu{b.D[6][v], b.D[7][v], b.D[8][v]};
    // cof [Xs Xt Xu] = (Xt x Xu, Xu x Xs, Xs x Xt) (mat.h); det = Xs . (Xt x Xu).
    const Vec3 c0 = cross(Xt, Xu);
    b.det[v] = dot(Xs, c0) / det_m;
    if (Normals) {
      const Vec3 c1 = cross(Xu, Xs), c2 = cross(Xs, Xt);
      const Vec3 n = b.nx[v] * c0 + b.ny[v] * c1 + b.nz[v] * c2;
      const double len = std::sqrt(dot(n, n)), inv = 1 / len;
      const bool unit = len > 0;  // normalized(): the zero vector stays
      b.Nx[v] = unit ? n.x * inv : n.x;
      b.Ny[v] = unit ? n.y * inv : n.y;
      b.Nz[v] = unit ? n.z * inv : n.z;
    }
  }
}

template <int Pt>
[[gnu::always_inline]] inline void cell_kernel(const CellData& cd, bool normals, int count,
                                               Block& b) {
  horner<Pt>(cd, (count + kLanes - 1) / kLanes, b);
  if (normals)
    finish<true>(count, cd.det_m, b);
  else
    finish<false>(count, cd.det_m, b);
}

// The kernels, one function per instruction set (the templates are inlined
// into it): fixed degrees 1..5, and the degree at run time above.
GLLAB_SPLINE_CLONES void run_kernel(const CellData& cd, bool normals, int count, Block& b) {
  switch (cd.degree) {
    case 1: cell_kernel<1>(cd, normals, count, b); break;
    case 2: cell_kernel<2>(cd, normals, count, b); break;
    case 3: cell_kernel<3>(cd, normals, count, b); break;
    case 4: cell_kernel<4>(cd, normals, count, b); break;
    case 5: cell_kernel<5>(cd, normals, count, b); break;
    default: cell_kernel<0>(cd, normals, count, b); break;
  }
}

/// d_e[k] = s_e[ord[k]], e = 0, 1, 2, k < count.
GLLAB_SPLINE_CLONES void gather3(const double* __restrict s0, const double* __restrict s1,
                                 const double* __restrict s2, const std::uint32_t* __restrict ord,
                                 int count, double* __restrict d0, double* __restrict d1,
                                 double* __restrict d2) {
  for (int k = 0; k < count; ++k) {
    const std::uint32_t i = ord[k];
    d0[k] = s0[i], d1[k] = s1[i], d2[k] = s2[i];
  }
}
/// d_e[ord[k]] = s_e[k], e = 0, 1, 2, k < count.
GLLAB_SPLINE_CLONES void scatter3(const double* __restrict s0, const double* __restrict s1,
                                  const double* __restrict s2, const std::uint32_t* __restrict ord,
                                  int count, double* __restrict d0, double* __restrict d1,
                                  double* __restrict d2) {
  for (int k = 0; k < count; ++k) {
    const std::uint32_t i = ord[k];
    d0[i] = s0[k], d1[i] = s1[k], d2[i] = s2[k];
  }
}
/// d_e[ord[k]] = s_e[k], e = 0 .. 3, k < count.
GLLAB_SPLINE_CLONES void scatter4(const double* __restrict s0, const double* __restrict s1,
                                  const double* __restrict s2, const double* __restrict s3,
                                  const std::uint32_t* __restrict ord, int count,
                                  double* __restrict d0, double* __restrict d1,
                                  double* __restrict d2, double* __restrict d3) {
  for (int k = 0; k < count; ++k) {
    const std::uint32_t i = ord[k];
    d0[i] = s0[k], d1[i] = s1[k], d2[i] = s2[k], d3[i] = s3[k];
  }
}

/// Block b <- the chunk's vertices ord[0 .. count); a copy when they are
/// consecutive (ord is increasing: the first and last tell).
void gather(const Chunk& c, const std::uint32_t* ord, int count, bool normals, Block& b) {
  const std::size_t n = std::size_t(count) * sizeof(double);
  if (ord[count - 1] - ord[0] == std::uint32_t(count - 1)) {
    const std::size_t i = ord[0];
    std::memcpy(b.s, &c.s[i], n), std::memcpy(b.t, &c.t[i], n), std::memcpy(b.u, &c.u[i], n);
    if (normals)
      std::memcpy(b.nx, &c.nx[i], n), std::memcpy(b.ny, &c.ny[i], n),
          std::memcpy(b.nz, &c.nz[i], n);
    return;
  }
  gather3(c.s.data(), c.t.data(), c.u.data(), ord, count, b.s, b.t, b.u);
  if (normals) gather3(c.nx.data(), c.ny.data(), c.nz.data(), ord, count, b.nx, b.ny, b.nz);
}

/// The chunk's results at ord[0 .. count) <- block b's.
void scatter(const Block& b, const std::uint32_t* ord, int count, bool normals, Chunk& c) {
  const std::size_t n = std::size_t(count) * sizeof(double);
  if (ord[count - 1] - ord[0] == std::uint32_t(count - 1)) {
    const std::size_t i = ord[0];
    std::memcpy(&c.X[i], b.X[0], n), std::memcpy(&c.Y[i], b.X[1], n);
    std::memcpy(&c.Z[i], b.X[2], n);
    std::memcpy(&c.det[i], b.det, n);
    if (normals)
      std::memcpy(&c.Nx[i], b.Nx, n), std::memcpy(&c.Ny[i], b.Ny, n),
          std::memcpy(&c.Nz[i], b.Nz, n);
    return;
  }
  scatter4(b.X[0], b.X[1], b.X[2], b.det, ord, count, c.X.data(), c.Y.data(), c.Z.data(),
           c.det.data());
  if (normals) scatter3(b.Nx, b.Ny, b.Nz, ord, count, c.Nx.data(), c.Ny.data(), c.Nz.data());
}

// ---- input and output: a float mesh or double points ------------------------------------

struct MeshIO {
  const float* pos;
  const float* nrm;  // null: no normals
  float* out_pos;
  float* out_nrm;
  float* out_det;
  std::size_t n;
  static constexpr const char* kWhat = "deform_mesh_fast: vertex ";
  Vec3 position(std::size_t v) const { return {pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]}; }
  Vec3 normal(std::size_t v) const { return {nrm[3 * v], nrm[3 * v + 1], nrm[3 * v + 2]}; }
  void put_position(std::size_t v, double x, double y, double z) const {
    float* q = out_pos + 3 * v;
    q[0] = float(x), q[1] = float(y), q[2] = float(z);
  }
  void put_normal(std::size_t v, double x, double y, double z) const {
    float* q = out_nrm + 3 * v;
    q[0] = float(x), q[1] = float(y), q[2] = float(z);
  }
  void put_det(std::size_t v, double d) const { out_det[v] = float(d); }
};

struct PointIO {
  const Vec3* pos;
  const Vec3* nrm;
  Vec3* out_pos;
  Vec3* out_nrm;
  double* out_det;
  std::size_t n;
  static constexpr const char* kWhat = "deform_points_fast: point ";
  Vec3 position(std::size_t v) const { return pos[v]; }
  Vec3 normal(std::size_t v) const { return nrm[v]; }
  void put_position(std::size_t v, double x, double y, double z) const { out_pos[v] = {x, y, z}; }
  void put_normal(std::size_t v, double x, double y, double z) const { out_nrm[v] = {x, y, z}; }
  void put_det(std::size_t v, double d) const { out_det[v] = d; }
};

/// What the vectorised passes over a chunk need of the lattice.
struct ChunkConsts {
  Vec3 origin, a, b, c;  // X0 and the columns of M^-1
  Vec3 S, T, U;          // the columns of M
  double slack;          // kBoxSlack, or deform_mesh's for float vertices
  int segments[3];
  std::uint32_t outside;
};

/// Mapper::local's arithmetic for the chunk's vertices c0 .. c0 + n - 1:
/// (s, t, u) = M^-1 (x - X0), inside when every coordinate is within
/// k.slack of [0, 1], then clamped; 0 or k.outside in ch.cell. Returns how
/// many positions are not finite. Branch-free, and every constant in a local
/// (a store through ch.cell could otherwise change k.outside): it vectorises.
template <class IO>
[[gnu::always_inline]] inline std::size_t local_pass(const ChunkConsts& k, const IO& io,
                                                     std::size_t c0, std::size_t n, Chunk& ch) {
  const Vec3 o = k.origin, a = k.a, b = k.b, c = k.c;
  const std::uint32_t outside = k.outside;
  const double lo = -k.slack, hi = 1 + k.slack;
  constexpr double kBig = std::numeric_limits<double>::max();
  double* __restrict ps = ch.s.data();
  double* __restrict pt = ch.t.data();
  double* __restrict pu = ch.u.data();
  std::uint32_t* __restrict pc = ch.cell.data();
  std::size_t bad = 0;
  for (std::size_t v = 0; v < n; ++v) {
    const Vec3 x = io.position(c0 + v);
    bad += !((std::fabs(x.x) <= kBig) & (std::fabs(x.y) <= kBig) & (std::fabs(x.z) <= kBig));
    const Vec3 d = x - o;
    // m_inv * d = d.x c0 + d.y c1 + d.z c2 (mat.h), component by component
    double s = d.x * a.x + d.y * b.x + d.z * c.x;
    double t = d.x * a.y + d.y * b.y + d.z * c.y;
    double u = d.x * a.z + d.y * b.z + d.z * c.z;
    const bool in =
        (s >= lo) & (s <= hi) & (t >= lo) & (t <= hi) & (u >= lo) & (u <= hi);
    // std::clamp(c, 0.0, 1.0), 0 outside (so that the spans below are defined)
    s = in ? (s < 0 ? 0 : s > 1 ? 1 : s) : 0;
    t = in ? (t < 0 ? 0 : t > 1 ? 1 : t) : 0;
    u = in ? (u < 0 ? 0 : u > 1 ? 1 : u) : 0;
    ps[v] = s, pt[v] = t, pu[v] = u;
    pc[v] = in ? 0 : outside;
  }
  return bad;
}

/// The cells of the chunk's inside vertices. In each direction the span is
/// floor(w * segments) unless w * segments is within 1e-9 of an integer: w
/// is then at a knot up to rounding (w * segments and the knots j /
/// segments are both within an ulp of exact), or w = 1, and the knots
/// themselves must decide (A2.1: knot[j] <= w < knot[j + 1], the last span
/// for w = 1). Those vertices are marked in ch.near for span_at_knot; the
/// loop has no table look-up and no branch: it vectorises. Returns how many
/// are marked.
[[gnu::always_inline]] inline std::size_t cell_pass(const ChunkConsts& k, std::size_t n,
                                                    Chunk& ch) {
  const int gs = k.segments[0], gt = k.segments[1], gu = k.segments[2];
  const double *__restrict ps = ch.s.data(), *__restrict pt = ch.t.data();
  const double* __restrict pu = ch.u.data();
  std::uint32_t* __restrict pc = ch.cell.data();
  std::uint8_t* __restrict pn = ch.near.data();
  constexpr double kNear = 1e-9;
  std::size_t near = 0;
  for (std::size_t v = 0; v < n; ++v) {
    const double fs = ps[v] * gs, ft = pt[v] * gt, fu = pu[v] * gu;
    // Clamped to the last span, so that a cell is always below k.outside (w = 1
    // gives r = 1 and is marked).
    const int i = std::min(static_cast<int>(fs), gs - 1);
    const int j = std::min(static_cast<int>(ft), gt - 1);
    const int l = std::min(static_cast<int>(fu), gu - 1);
    const double rs = fs - i, rt = ft - j, ru = fu - l;  // in [0, 1]: fs >= 0
    const bool close = (rs < kNear) | (rs > 1 - kNear) | (rt < kNear) | (rt > 1 - kNear) |
                       (ru < kNear) | (ru > 1 - kNear);
    // Inside, pc[v] is 0; outside it is k.outside, more than any cell.
    pc[v] = std::max(pc[v], std::uint32_t((i * gt + j) * gu + l));
    pn[v] = close;
    near += close;
  }
  return near;
}

/// A2.1's span for w in [0, 1] from the knots themselves (ch.near's vertices;
/// floor(w segments) is at most one off, bench/README.md's ffd section).
int span_at_knot(const AxisTable& a, double w) {
  int j = std::min(static_cast<int>(w * a.segments), a.segments - 1);
  j += (w >= a.upper[std::size_t(j)]) - (w < a.lower[std::size_t(j)]);
  return j;
}

template <class IO>
[[gnu::always_inline]] inline void normal_pass(const ChunkConsts& k, const IO& io, std::size_t c0,
                                               std::size_t n, Chunk& ch) {
  const Vec3 S = k.S, T = k.T, U = k.U;
  double* __restrict px = ch.nx.data();
  double* __restrict py = ch.ny.data();
  double* __restrict pz = ch.nz.data();
  for (std::size_t v = 0; v < n; ++v) {
    const Vec3 nn = io.normal(c0 + v);  // M^T n
    px[v] = dot(S, nn), py[v] = dot(T, nn), pz[v] = dot(U, nn);
  }
}

/// The chunk's results to the output, and their statistics (the inside
/// vertices' det J); outside vertices are written afterwards.
template <class IO>
[[gnu::always_inline]] inline void write_pass(const IO& io, std::size_t c0, std::size_t n,
                                              bool normals, const Chunk& ch) {
  for (std::size_t v = 0; v < n; ++v) {
    io.put_position(c0 + v, ch.X[v], ch.Y[v], ch.Z[v]);
    io.put_det(c0 + v, ch.det[v]);
  }
  if (normals)
    for (std::size_t v = 0; v < n; ++v) io.put_normal(c0 + v, ch.Nx[v], ch.Ny[v], ch.Nz[v]);
}

// One function per instruction set for each pass and input type.
GLLAB_SPLINE_CLONES std::size_t local_mesh(const ChunkConsts& k, const MeshIO& io, std::size_t c0,
                                           std::size_t n, bool spans, bool normals, Chunk& ch,
                                           std::size_t& near) {
  if (normals) normal_pass(k, io, c0, n, ch);
  const std::size_t bad = local_pass(k, io, c0, n, ch);
  near = spans ? cell_pass(k, n, ch) : 0;
  return bad;
}
GLLAB_SPLINE_CLONES std::size_t local_points(const ChunkConsts& k, const PointIO& io,
                                             std::size_t c0, std::size_t n, bool spans,
                                             bool normals, Chunk& ch, std::size_t& near) {
  if (normals) normal_pass(k, io, c0, n, ch);
  const std::size_t bad = local_pass(k, io, c0, n, ch);
  near = spans ? cell_pass(k, n, ch) : 0;
  return bad;
}
std::size_t local(const ChunkConsts& k, const MeshIO& io, std::size_t c0, std::size_t n,
                  bool spans, bool normals, Chunk& ch, std::size_t& near) {
  return local_mesh(k, io, c0, n, spans, normals, ch, near);
}
std::size_t local(const ChunkConsts& k, const PointIO& io, std::size_t c0, std::size_t n,
                  bool spans, bool normals, Chunk& ch, std::size_t& near) {
  return local_points(k, io, c0, n, spans, normals, ch, near);
}
GLLAB_SPLINE_CLONES void write_mesh(const MeshIO& io, std::size_t c0, std::size_t n, bool normals,
                                    const Chunk& ch) {
  write_pass(io, c0, n, normals, ch);
}
void write(const MeshIO& io, std::size_t c0, std::size_t n, bool normals, const Chunk& ch) {
  write_mesh(io, c0, n, normals, ch);
}
void write(const PointIO& io, std::size_t c0, std::size_t n, bool normals, const Chunk& ch) {
  write_pass(io, c0, n, normals, ch);
}

struct Stats {
  std::size_t outside = 0, folded = 0;
  double lo = INFINITY, hi = -INFINITY;
};

/// folded, min and max of det J over the chunk's inside vertices.
void chunk_stats(const Chunk& ch, std::size_t n, std::uint32_t outside, Stats& st) {
  std::size_t folded = 0;
  double lo = st.lo, hi = st.hi;
  for (std::size_t v = 0; v < n; ++v) {
    if (ch.cell[v] == outside) continue;
    const double d = ch.det[v];
    folded += d <= 0;
    lo = std::min(lo, d), hi = std::max(hi, d);
  }
  st.folded += folded, st.lo = lo, st.hi = hi;
}

/// Sorts the chunk's vertices by cell into ch.order, stably (step 5).
void bucket(std::size_t cells, std::size_t n, Chunk& ch) {
  if (cells + 1 > 4 * kChunk) {  // many cells: a comparison sort
    for (std::size_t v = 0; v < n; ++v) ch.order[v] = std::uint32_t(v);
    std::stable_sort(ch.order.begin(), ch.order.begin() + std::ptrdiff_t(n),
                     [&](std::uint32_t a, std::uint32_t b) { return ch.cell[a] < ch.cell[b]; });
    return;
  }
  ch.counts.assign(cells + 2, 0);
  for (std::size_t v = 0; v < n; ++v) ++ch.counts[ch.cell[v] + 1];
  for (std::size_t c = 1; c < ch.counts.size(); ++c) ch.counts[c] += ch.counts[c - 1];
  for (std::size_t v = 0; v < n; ++v) ch.order[ch.counts[ch.cell[v]]++] = std::uint32_t(v);
}

template <class IO>
[[noreturn]] void throw_not_finite(const IO& io, std::size_t c0, std::size_t n) {
  for (std::size_t v = c0; v < c0 + n; ++v) {
    const Vec3 x = io.position(v);
    if (!std::isfinite(x.x) || !std::isfinite(x.y) || !std::isfinite(x.z))
      throw std::invalid_argument(IO::kWhat + std::to_string(v) + " " + vec_text(x) +
                                  " is not finite");
  }
  throw std::logic_error("fast_deform: a non-finite position was counted but not found");
}

/// Every vertex of `io` through the lattice.
template <class IO>
void deform_all(const Setup& st, const IO& io, bool normals, double slack, Stats& stats) {
  const std::size_t total = io.n;
  if (total == 0) return;
  Chunk ch;
  ChunkConsts k{st.origin, st.m_inv.c0, st.m_inv.c1, st.m_inv.c2, st.m.c0, st.m.c1, st.m.c2,
                slack, {1, 1, 1}, std::uint32_t(st.cells)};
  if (st.fast)
    for (int e = 0; e < 3; ++e) k.segments[e] = st.axis[e].segments;
  const bool spans = st.cells > 1;
  CellCache cache(st);
  const std::unique_ptr<Block> own(new Block());  // 13 kB: not on the stack
  Block& blk = *own;
  std::unique_ptr<VolumeEvaluator> textbook;
  if (!st.fast) textbook = std::make_unique<VolumeEvaluator>(*st.volume);

  for (std::size_t c0 = 0; c0 < total; c0 += kChunk) {
    const std::size_t n = std::min(kChunk, total - c0);
    std::size_t near = 0;
    if (local(k, io, c0, n, spans, normals && st.fast, ch, near) > 0) throw_not_finite(io, c0, n);
    for (std::size_t v = 0; near > 0 && v < n; ++v)
      if (ch.near[v]) {
        --near;
        if (ch.cell[v] == k.outside) continue;
        ch.cell[v] = std::uint32_t(
            (std::size_t(span_at_knot(st.axis[0], ch.s[v])) * st.axis[1].segments +
             std::size_t(span_at_knot(st.axis[1], ch.t[v]))) *
                st.axis[2].segments +
            std::size_t(span_at_knot(st.axis[2], ch.u[v])));
      }
    bucket(st.cells, n, ch);
    std::size_t outside_begin = n;  // the outside bucket, the last, is order[outside_begin ..)
    for (std::size_t begin = 0; begin < n;) {
      const std::uint32_t cell = ch.cell[ch.order[begin]];
      std::size_t end = begin + 1;
      while (end < n && ch.cell[ch.order[end]] == cell) ++end;
      if (cell == k.outside) {
        outside_begin = begin;  // deform_mesh's values, written after write() below
      } else if (textbook) {
        // Above kMaxFastDegree: Mapper::operator()'s arithmetic, vertex by vertex.
        for (std::size_t e = begin; e < end; ++e) {
          const std::size_t i = ch.order[e];
          const VolumeDerivs d = (*textbook)(ch.s[i], ch.t[i], ch.u[i]);
          ch.X[i] = d.X.x, ch.Y[i] = d.X.y, ch.Z[i] = d.X.z;
          ch.det[i] = det(d.jacobian()) / st.det_m;
          if (normals) {
            const Vec3 nn = deform_normal(d.jacobian() * st.m_inv, io.normal(c0 + i));
            ch.Nx[i] = nn.x, ch.Ny[i] = nn.y, ch.Nz[i] = nn.z;
          }
        }
      } else {
        const std::size_t su = std::size_t(st.axis[2].segments);
        const std::size_t stt = std::size_t(st.axis[1].segments);
        const CellData cd{cache.get(cell), st.degree, st.axis[0].centre[cell / (stt * su)],
                          st.axis[1].centre[cell / su % stt], st.axis[2].centre[cell % su],
                          st.det_m};
        const std::uint32_t* ord = &ch.order[begin];
        const std::size_t count = end - begin;
        for (std::size_t b0 = 0; b0 < count; b0 += kBlock) {
          const int m = int(std::min<std::size_t>(kBlock, count - b0));
          gather(ch, ord + b0, m, normals, blk);
          run_kernel(cd, normals, m, blk);
          scatter(blk, ord + b0, m, normals, ch);
        }
      }
      begin = end;
    }
    write(io, c0, n, normals, ch);
    chunk_stats(ch, n, k.outside, stats);
    for (std::size_t e = outside_begin; e < n; ++e) {
      const std::size_t i = c0 + ch.order[e];
      const Vec3 x = io.position(i);
      io.put_position(i, x.x, x.y, x.z);
      io.put_det(i, 1.0);
      if (normals) {
        const Vec3 nn = deform_normal(Mat3{}, io.normal(i));
        io.put_normal(i, nn.x, nn.y, nn.z);
      }
    }
    stats.outside += n - outside_begin;
  }
}

/// |A|_inf, the largest row sum.
double norm_inf(const Mat3& a) {
  const Mat3 t = transpose(a);
  const auto row = [](Vec3 r) { return std::fabs(r.x) + std::fabs(r.y) + std::fabs(r.z); };
  return std::max({row(t.c0), row(t.c1), row(t.c2)});
}

/// deform_mesh's slack for float vertices (ffd.h; the same expression as in
/// ffd.cpp, so the same bits): a vertex on a face of a box that is not
/// axis-aligned is off it by up to |M^-1| 2^-24 |x| in (s, t, u).
double mesh_slack(const Frame& f, const Mat3& m_inv) {
  const double box_size = std::max({std::fabs(f.origin.x), std::fabs(f.origin.y),
                                    std::fabs(f.origin.z)}) + norm_inf(f.matrix());
  return std::max(kBoxSlack, norm_inf(m_inv) * box_size * 0x1p-23);
}

}  // namespace

void deform_mesh_fast(const Lattice& lattice, const IndexedMesh& mesh, DeformedMesh& out) {
  const Setup st(lattice);
  const std::size_t n = mesh.vertex_count();
  const bool normals = mesh.normals.size() == mesh.positions.size();
  out.mesh.indices = mesh.indices;
  out.mesh.colours = mesh.colours;
  // deform_mesh's sizes; floats past the last whole vertex stay 0 there.
  out.mesh.positions.resize(mesh.positions.size());
  std::fill(out.mesh.positions.begin() + std::ptrdiff_t(3 * n), out.mesh.positions.end(), 0.0f);
  if (normals) {
    out.mesh.normals.resize(mesh.normals.size());
    std::fill(out.mesh.normals.begin() + std::ptrdiff_t(3 * n), out.mesh.normals.end(), 0.0f);
  } else {
    out.mesh.normals.clear();
  }
  out.det.resize(n);
  const MeshIO io{mesh.positions.data(), normals ? mesh.normals.data() : nullptr,
                  out.mesh.positions.data(), normals ? out.mesh.normals.data() : nullptr,
                  out.det.data(), n};
  Stats stats;
  deform_all(st, io, normals, mesh_slack(lattice.frame, st.m_inv), stats);
  out.outside = stats.outside;
  out.folded = stats.folded;
  out.min_det = out.max_det = 1;
  if (stats.outside < n) out.min_det = stats.lo, out.max_det = stats.hi;
}

DeformedMesh deform_mesh_fast(const Lattice& lattice, const IndexedMesh& mesh) {
  DeformedMesh out;
  deform_mesh_fast(lattice, mesh, out);
  return out;
}

DeformedPoints deform_points_fast(const Lattice& lattice, const std::vector<Vec3>& x,
                                  const std::vector<Vec3>& normals) {
  const Setup st(lattice);
  if (!normals.empty() && normals.size() != x.size())
    throw std::invalid_argument("deform_points_fast: " + std::to_string(normals.size()) +
                                " normals for " + std::to_string(x.size()) + " points");
  DeformedPoints out;
  out.x.resize(x.size());
  out.normals.resize(normals.size());
  out.det.resize(x.size());
  const bool with = !normals.empty();
  const PointIO io{x.data(), with ? normals.data() : nullptr, out.x.data(),
                   with ? out.normals.data() : nullptr, out.det.data(), x.size()};
  Stats stats;
  deform_all(st, io, with, kBoxSlack, stats);
  out.outside = stats.outside;
  out.folded = stats.folded;
  if (stats.outside < x.size()) out.min_det = stats.lo, out.max_det = stats.hi;
  return out;
}

}  // namespace gllab::deform
