// common/deform/ffd.cpp — free-form deformation of points and meshes,
// folds and volumes (ffd.h).
#include "deform/ffd.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "spline/quadrature.h"

namespace gllab::deform {

namespace {

std::string num(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string vec_text(Vec3 v) {
  return "(" + num("%.17g", v.x) + ", " + num("%.17g", v.y) + ", " + num("%.17g", v.z) + ")";
}

bool finite(Vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// det M of a frame, checked: a lattice needs a right-handed box with volume.
double frame_det(const Frame& f) {
  const double d = det(f.matrix());
  if (!(d > 0) || !std::isfinite(d) || !finite(f.origin))
    throw std::invalid_argument("lattice frame: det [S T U] = " + num("%.17g", d) +
                                " (the box must have volume and S, T, U be right-handed)");
  return d;
}

// Everything one lattice needs per point, computed once: the evaluator, the
// frame's inverse and det M.
struct Mapper {
  explicit Mapper(const Lattice& l)
      : eval(l.volume), frame(l.frame), det_m(frame_det(l.frame)),
        m_inv(inverse(l.frame.matrix())) {}

  // (s, t, u) clamped onto the box when within `slack`; false when outside.
  bool local(Vec3 x, Vec3& stu) const {
    stu = m_inv * (x - frame.origin);
    double* w[3] = {&stu.x, &stu.y, &stu.z};
    for (double* c : w) {
      if (!(*c >= -slack && *c <= 1 + slack)) return false;
      *c = std::clamp(*c, 0.0, 1.0);
    }
    return true;
  }

  FfdPoint operator()(Vec3 x) const {
    FfdPoint r;
    r.x = x;
    Vec3 stu;
    if (!local(x, stu)) return r;
    const VolumeDerivs d = eval(stu.x, stu.y, stu.z);
    r.inside = true;
    r.x = d.X;
    r.J = d.jacobian() * m_inv;  // [Xs Xt Xu] M^-1
    r.det = det(d.jacobian()) / det_m;
    return r;
  }

  VolumeEvaluator eval;
  Frame frame;
  double det_m;
  Mat3 m_inv;
  double slack = kBoxSlack;
};

// |A|_inf, the largest row sum.
double norm_inf(const Mat3& a) {
  const Mat3 t = transpose(a);
  const auto row = [](Vec3 r) { return std::fabs(r.x) + std::fabs(r.y) + std::fabs(r.z); };
  return std::max({row(t.c0), row(t.c1), row(t.c2)});
}

}  // namespace

Frame box_frame(Vec3 lo, Vec3 hi) {
  if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z) || !finite(lo) || !finite(hi))
    throw std::invalid_argument("box_frame: lo " + vec_text(lo) + " must lie below hi " +
                                vec_text(hi) + " in every coordinate");
  return {lo, {hi.x - lo.x, 0, 0}, {0, hi.y - lo.y, 0}, {0, 0, hi.z - lo.z}};
}

Lattice identity_lattice(const Frame& frame, const Volume& unit) {
  frame_det(frame);
  validate(unit);
  Lattice l{frame, unit};
  for (Vec3& p : l.volume.P) p = frame.origin + frame.matrix() * p;
  return l;
}

Vec3 local_coordinates(const Frame& frame, Vec3 x) {
  frame_det(frame);
  // M^-1 = cof(M)^T / det M is Cramer's rule, Sederberg and Parry's eq. (1):
  // s = (T x U).(x - X0) / (T x U).S, and so on.
  return inverse(frame.matrix()) * (x - frame.origin);
}

FfdPoint ffd_point(const Lattice& lattice, Vec3 x) {
  if (!finite(x)) throw std::invalid_argument("ffd_point: x = " + vec_text(x) + " is not finite");
  return Mapper(lattice)(x);
}

Vec3 deform_normal(const Mat3& J, Vec3 n) { return normalized(cofactor(J) * n); }

DeformedMesh deform_mesh(const Lattice& lattice, const IndexedMesh& mesh) {
  Mapper map(lattice);
  // The vertices are floats: one on a face of a box that is not axis-aligned
  // is off the face by up to 2^-24 |x|, in (s, t, u) up to |M^-1| 2^-24 |x|,
  // far more than kBoxSlack. Within twice that it still counts as on the box.
  const Frame& f = lattice.frame;
  const double box_size = std::max({std::fabs(f.origin.x), std::fabs(f.origin.y),
                                    std::fabs(f.origin.z)}) + norm_inf(f.matrix());
  map.slack = std::max(kBoxSlack, norm_inf(map.m_inv) * box_size * 0x1p-23);
  const std::size_t n = mesh.vertex_count();
  const bool normals = mesh.normals.size() == mesh.positions.size();
  DeformedMesh out;
  out.mesh.indices = mesh.indices;
  out.mesh.colours = mesh.colours;
  out.mesh.positions.resize(mesh.positions.size());
  if (normals) out.mesh.normals.resize(mesh.normals.size());
  out.det.resize(n);
  double lo = INFINITY, hi = -INFINITY;
  for (std::size_t v = 0; v < n; ++v) {
    const float* p = &mesh.positions[3 * v];
    const Vec3 x{p[0], p[1], p[2]};
    if (!finite(x))
      throw std::invalid_argument("deform_mesh: vertex " + std::to_string(v) + " " + vec_text(x) +
                                  " is not finite");
    const FfdPoint f = map(x);
    float* q = &out.mesh.positions[3 * v];
    q[0] = float(f.x.x), q[1] = float(f.x.y), q[2] = float(f.x.z);
    if (normals) {
      const float* m = &mesh.normals[3 * v];
      const Vec3 nn = deform_normal(f.J, {m[0], m[1], m[2]});
      float* o = &out.mesh.normals[3 * v];
      o[0] = float(nn.x), o[1] = float(nn.y), o[2] = float(nn.z);
    }
    out.det[v] = float(f.det);
    if (!f.inside) {
      ++out.outside;
      continue;
    }
    out.folded += f.det <= 0;
    lo = std::min(lo, f.det), hi = std::max(hi, f.det);
  }
  if (out.outside < n) out.min_det = lo, out.max_det = hi;
  return out;
}

std::vector<float> face_averaged_normals(const IndexedMesh& mesh) {
  std::vector<Vec3> sum(mesh.vertex_count());
  const auto at = [&](std::uint32_t i) {
    const float* p = &mesh.positions[3 * std::size_t(i)];
    return Vec3{p[0], p[1], p[2]};
  };
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    // |(b - a) x (c - a)| is twice the area: larger triangles weigh more.
    const Vec3 n = cross(at(b) - at(a), at(c) - at(a));
    sum[a] += n, sum[b] += n, sum[c] += n;
  }
  std::vector<float> out(3 * sum.size());
  for (std::size_t v = 0; v < sum.size(); ++v) {
    const Vec3 n = normalized(sum[v]);
    out[3 * v] = float(n.x), out[3 * v + 1] = float(n.y), out[3 * v + 2] = float(n.z);
  }
  return out;
}

AngleStats normal_angles(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size() || a.size() % 3 != 0)
    throw std::invalid_argument("normal_angles: " + std::to_string(a.size()) + " and " +
                                std::to_string(b.size()) + " floats (3 per normal, as many each)");
  AngleStats s;
  const double to_deg = 180 / std::acos(-1.0);
  const std::size_t n = a.size() / 3;
  for (std::size_t v = 0; v < n; ++v) {
    const Vec3 p{a[3 * v], a[3 * v + 1], a[3 * v + 2]}, q{b[3 * v], b[3 * v + 1], b[3 * v + 2]};
    // atan2(|p x q|, p . q): accurate for small angles, where acos is not.
    const double angle = std::atan2(norm(cross(p, q)), dot(p, q)) * to_deg;
    s.max_deg = std::max(s.max_deg, angle);
    s.mean_deg += angle / double(n);
  }
  return s;
}

Fold find_fold(const Lattice& lattice, int samples) {
  if (samples < 1 || samples > 64)
    throw std::invalid_argument("find_fold: samples = " + std::to_string(samples) +
                                " (must be 1..64)");
  const Mapper map(lattice);
  const std::array<int, 3>& c = lattice.volume.count;
  const int g[3] = {samples * (c[0] - 1), samples * (c[1] - 1), samples * (c[2] - 1)};
  Fold f;
  f.min_det = INFINITY;
  for (int i = 0; i <= g[0]; ++i)
    for (int j = 0; j <= g[1]; ++j)
      for (int k = 0; k <= g[2]; ++k) {
        const Vec3 stu{double(i) / g[0], double(j) / g[1], double(k) / g[2]};
        const double d = det(map.eval(stu.x, stu.y, stu.z).jacobian()) / map.det_m;
        if (d < f.min_det) f.min_det = d, f.stu = stu;
      }
  f.folds = f.min_det <= 0;
  f.x = lattice.frame.origin + lattice.frame.matrix() * f.stu;
  return f;
}

std::string fold_text(const Fold& fold) {
  if (!fold.folds) return "no fold: det J >= " + num("%.3g", fold.min_det);
  return "folds: det J " + num("%.3g", fold.min_det) + " at (s, t, u) = (" +
         num("%.2f", fold.stu.x) + ", " + num("%.2f", fold.stu.y) + ", " +
         num("%.2f", fold.stu.z) + ")";
}

void require_no_fold(const Lattice& lattice, int samples) {
  const Fold f = find_fold(lattice, samples);
  if (f.folds) throw std::invalid_argument(fold_text(f));
}

double deformed_volume(const Lattice& lattice, Vec3 lo, Vec3 hi, int points) {
  const double a[3] = {lo.x, lo.y, lo.z}, b[3] = {hi.x, hi.y, hi.z};
  for (int k = 0; k < 3; ++k)
    if (!(0 <= a[k] && a[k] < b[k] && b[k] <= 1))
      throw std::invalid_argument("deformed_volume: box " + vec_text(lo) + " .. " + vec_text(hi) +
                                  " (must have 0 <= lo < hi <= 1 in s, t, u)");
  if (points < 1 || points > 16)
    throw std::invalid_argument("deformed_volume: points = " + std::to_string(points) +
                                " (must be 1..16)");
  const spline::GaussRule rule = spline::gauss_legendre(points);
  const VolumeEvaluator eval(lattice.volume);
  // The nodes of each direction: the rule on every knot span that [a, b] meets.
  std::array<std::vector<double>, 3> x, w;
  for (int k = 0; k < 3; ++k) {
    std::vector<double> cuts = {a[k]};
    for (double knot : volume_knots(lattice.volume, k))
      if (knot > cuts.back() && knot < b[k]) cuts.push_back(knot);
    cuts.push_back(b[k]);
    for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
      const double half = (cuts[c + 1] - cuts[c]) / 2, mid = (cuts[c + 1] + cuts[c]) / 2;
      for (int r = 0; r < points; ++r) {
        x[k].push_back(mid + half * rule.x[r]);
        w[k].push_back(half * rule.w[r]);
      }
    }
  }
  double sum = 0;
  for (std::size_t i = 0; i < x[0].size(); ++i)
    for (std::size_t j = 0; j < x[1].size(); ++j)
      for (std::size_t k = 0; k < x[2].size(); ++k)
        sum += w[0][i] * w[1][j] * w[2][k] * det(eval(x[0][i], x[1][j], x[2][k]).jacobian());
  return sum;
}

}  // namespace gllab::deform
