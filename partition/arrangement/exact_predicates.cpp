// The only CGAL translation unit of the arrangement: interval filters (CGAL::Interval_nt) with
// exact fallbacks (CGAL::Mpzf, exact for sums and products of doubles).

#include "partition/arrangement/exact_predicates.h"

#include <CGAL/Interval_nt.h>
#include <CGAL/Mpzf.h>
#include <CGAL/determinant.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace linesurf::partition {
namespace {

// Unprotected intervals need the rounding mode upward; each predicate sets it once around its
// interval part (WithUpwardRounding) instead of once per operation, as Interval_nt<true> does
// (city-100: evidence 13.2 -> 3.2 s, the same bytes). The exact fallbacks
// run in the default mode.
using Interval = CGAL::Interval_nt<false>;
using Exact = CGAL::Mpzf;

/// f() under upward rounding, the previous mode restored after; f must not let an Interval out.
template <typename F>
auto WithUpwardRounding(const F& f) {
  const CGAL::Protect_FPU_rounding<true> upward;
  return f();
}

/// Relative rounding-error bound of the double filter that evaluates a plane over a box of
/// coordinates (a handful of products and sums; generous against the ~4u worst case).
constexpr double kFilterRelativeError = 1e-14;
/// Absolute slack of the same filter (covers underflow).
constexpr double kFilterAbsoluteError = 1e-300;

/// Relative width above which a vertex box is recomputed exactly (tighter boxes mean fewer exact
/// sign fallbacks later).
constexpr double kVertexBoundsRelativeWidth = 1e-10;

int SignOf(const Exact& x) { return static_cast<int>(CGAL::sign(x)); }

/// -1/0/+1 when the interval decides the sign, 2 when uncertain.
int SignOf(const Interval& x) {
  if (x.inf() > 0) return 1;
  if (x.sup() < 0) return -1;
  if (x.inf() == 0 && x.sup() == 0) return 0;
  return 2;
}

/// The signs of several 2x2 minors: one certainly nonzero, or some uncertain.
struct MinorSigns {
  bool nonzero = false;
  bool uncertain = false;
  void Add(int sign) {
    nonzero = nonzero || sign == 1 || sign == -1;
    uncertain = uncertain || sign == 2;
  }
};

void CountFallback(ExactCounter* counter) {
  if (counter != nullptr) counter->exact_fallbacks.fetch_add(1, std::memory_order_relaxed);
}

template <typename T>
T Det3(const Vec3& a, const Vec3& b, const Vec3& c) {
  return CGAL::determinant(T(a[0]), T(a[1]), T(a[2]), T(b[0]), T(b[1]), T(b[2]), T(c[0]), T(c[1]),
                           T(c[2]));
}

template <typename T>
T Det4(const Eigen::Vector4d& a, const Eigen::Vector4d& b, const Eigen::Vector4d& c,
       const Eigen::Vector4d& d) {
  return CGAL::determinant(T(a[0]), T(a[1]), T(a[2]), T(a[3]), T(b[0]), T(b[1]), T(b[2]), T(b[3]),
                           T(c[0]), T(c[1]), T(c[2]), T(c[3]), T(d[0]), T(d[1]), T(d[2]), T(d[3]));
}

template <typename T>
T Eval(const Eigen::Vector4d& plane, const Vec3& p) {
  return T(plane[0]) * T(p[0]) + T(plane[1]) * T(p[1]) + T(plane[2]) * T(p[2]) + T(plane[3]);
}

template <typename T>
T Dot(const Vec3& n, const Vec3& v) {
  return T(n[0]) * T(v[0]) + T(n[1]) * T(v[1]) + T(n[2]) * T(v[2]);
}

/// The three numerators and the denominator of Cramer's rule for N x = -d.
template <typename T>
void Cramer(const Eigen::Vector4d& i, const Eigen::Vector4d& j, const Eigen::Vector4d& k,
            T num[3], T& den) {
  const Vec3 ni = i.head<3>(), nj = j.head<3>(), nk = k.head<3>();
  den = Det3<T>(ni, nj, nk);
  for (int c = 0; c < 3; ++c) {
    Vec3 ri = ni, rj = nj, rk = nk;
    ri[c] = -i[3];
    rj[c] = -j[3];
    rk[c] = -k[3];
    num[c] = Det3<T>(ri, rj, rk);
  }
}

}  // namespace

int FilteredBoxSide(const Eigen::Vector4d& plane, const Vec3& lo, const Vec3& hi) {
  double vmin = plane[3];
  double vmax = plane[3];
  double magnitude = std::abs(plane[3]);
  for (int c = 0; c < 3; ++c) {
    const double a = plane[c];
    const double x = a * lo[c];
    const double y = a * hi[c];
    vmin += std::min(x, y);
    vmax += std::max(x, y);
    magnitude += std::max(std::abs(x), std::abs(y));
  }
  const double err = kFilterRelativeError * magnitude + kFilterAbsoluteError;
  if (vmin - err > 0) return 1;
  if (vmax + err < 0) return -1;
  return 0;
}

int ExactSignAtPoint(const Eigen::Vector4d& plane, const Vec3& p, ExactCounter* counter) {
  // Plain doubles first, without the rounding-mode switch: the sight-ray walks ask this at
  // every plane of every cell they cross.
  if (const int f = FilteredBoxSide(plane, p, p); f != 0) return f;
  const int s = WithUpwardRounding([&] { return SignOf(Eval<Interval>(plane, p)); });
  if (s != 2) return s;
  CountFallback(counter);
  return SignOf(Eval<Exact>(plane, p));
}

int ExactSignDot(const Vec3& n, const Vec3& v, ExactCounter* counter) {
  if (const int f = FilteredBoxSide(Eigen::Vector4d(n[0], n[1], n[2], 0.0), v, v); f != 0) {
    return f;
  }
  const int s = WithUpwardRounding([&] { return SignOf(Dot<Interval>(n, v)); });
  if (s != 2) return s;
  CountFallback(counter);
  return SignOf(Dot<Exact>(n, v));
}

int ExactSignDet3(const Vec3& n1, const Vec3& n2, const Vec3& n3, ExactCounter* counter) {
  const int s = WithUpwardRounding([&] { return SignOf(Det3<Interval>(n1, n2, n3)); });
  if (s != 2) return s;
  CountFallback(counter);
  return SignOf(Det3<Exact>(n1, n2, n3));
}

int ExactSignAtVertex(const Eigen::Vector4d& i, const Eigen::Vector4d& j, const Eigen::Vector4d& k,
                      const Eigen::Vector4d& l, ExactCounter* counter) {
  auto [s4, s3] = WithUpwardRounding([&] {
    return std::pair{SignOf(Det4<Interval>(i, j, k, l)),
                     SignOf(Det3<Interval>(i.head<3>(), j.head<3>(), k.head<3>()))};
  });
  if (s4 == 2 || s3 == 2) {
    CountFallback(counter);
    if (s4 == 2) s4 = SignOf(Det4<Exact>(i, j, k, l));
    if (s3 == 2) s3 = SignOf(Det3<Exact>(i.head<3>(), j.head<3>(), k.head<3>()));
  }
  return s4 * s3;
}

int ExactProportionality(const Eigen::Vector4d& p, const Eigen::Vector4d& q, ExactCounter* counter) {
  // Proportional iff every 2x2 minor p_a q_b - p_b q_a vanishes.
  const MinorSigns minors = WithUpwardRounding([&] {
    MinorSigns m;
    for (int a = 0; a < 4; ++a) {
      for (int b = a + 1; b < 4; ++b) {
        m.Add(SignOf(Interval(p[a]) * Interval(q[b]) - Interval(p[b]) * Interval(q[a])));
      }
    }
    return m;
  });
  if (minors.nonzero) return 0;
  if (minors.uncertain) {
    CountFallback(counter);
    for (int a = 0; a < 4; ++a) {
      for (int b = a + 1; b < 4; ++b) {
        if (SignOf(Exact(p[a]) * Exact(q[b]) - Exact(p[b]) * Exact(q[a])) != 0) return 0;
      }
    }
  }
  // Proportional: the sign of the factor is the sign of p.q over the (nonzero) normals.
  const double dot = p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
  if (dot != 0) return dot > 0 ? 1 : -1;
  for (int a = 0; a < 4; ++a) {
    if (p[a] != 0 && q[a] != 0) return (p[a] > 0) == (q[a] > 0) ? 1 : -1;
  }
  return 0;
}

bool ExactParallelNormals(const Eigen::Vector4d& p, const Eigen::Vector4d& q, ExactCounter* counter) {
  const Vec3 n = p.head<3>(), m = q.head<3>();
  const MinorSigns minors = WithUpwardRounding([&] {
    MinorSigns signs;
    for (int a = 0; a < 3; ++a) {
      const int b = (a + 1) % 3;
      signs.Add(SignOf(Interval(n[a]) * Interval(m[b]) - Interval(n[b]) * Interval(m[a])));
    }
    return signs;
  });
  if (minors.nonzero) return false;
  if (minors.uncertain) {
    CountFallback(counter);
    for (int a = 0; a < 3; ++a) {
      const int b = (a + 1) % 3;
      if (SignOf(Exact(n[a]) * Exact(m[b]) - Exact(n[b]) * Exact(m[a])) != 0) return false;
    }
  }
  return true;
}

namespace {

/// (a x b) . (p x q) (Binet-Cauchy) and (a x l) . (b x l) with l = p x q, in T.
template <typename T>
void AngularTerms(const Vec3& a, const Vec3& b, const Vec3& p, const Vec3& q, T& orientation,
                  T& dot) {
  orientation = Dot<T>(a, p) * Dot<T>(b, q) - Dot<T>(a, q) * Dot<T>(b, p);
  const T l[3] = {T(p[1]) * T(q[2]) - T(p[2]) * T(q[1]), T(p[2]) * T(q[0]) - T(p[0]) * T(q[2]),
                  T(p[0]) * T(q[1]) - T(p[1]) * T(q[0])};
  T al = T(a[0]) * l[0] + T(a[1]) * l[1] + T(a[2]) * l[2];
  T bl = T(b[0]) * l[0] + T(b[1]) * l[1] + T(b[2]) * l[2];
  T ll = l[0] * l[0] + l[1] * l[1] + l[2] * l[2];
  dot = Dot<T>(a, b) * ll - al * bl;
}

}  // namespace

AngularSigns ExactAngularSigns(const Vec3& a, const Vec3& b, const Vec3& p, const Vec3& q,
                               ExactCounter* counter) {
  // (a x l) x (b x l) = det[a, b, l] l, so the orientation is the sign of (a x b) . l.
  AngularSigns s = WithUpwardRounding([&] {
    Interval io, id;
    AngularTerms<Interval>(a, b, p, q, io, id);
    return AngularSigns{SignOf(io), SignOf(id)};
  });
  if (s.orientation == 2 || s.dot == 2) {
    CountFallback(counter);
    Exact eo, ed;
    AngularTerms<Exact>(a, b, p, q, eo, ed);
    s = {SignOf(eo), SignOf(ed)};
  }
  return s;
}

VertexBounds ComputeVertexBounds(const Eigen::Vector4d& i, const Eigen::Vector4d& j,
                                 const Eigen::Vector4d& k, ExactCounter* counter) {
  Interval x[3];
  const bool tight = WithUpwardRounding([&] {
    Interval num[3];
    Interval den;
    Cramer<Interval>(i, j, k, num, den);
    if (SignOf(den) != 1 && SignOf(den) != -1) return false;
    bool narrow = true;
    for (int c = 0; c < 3; ++c) {
      x[c] = num[c] / den;
      const double width = x[c].sup() - x[c].inf();
      if (!(width <= kVertexBoundsRelativeWidth * (1.0 + std::abs(x[c].inf())))) narrow = false;
    }
    return narrow;
  });
  if (!tight) {
    CountFallback(counter);
    Exact enum_[3];
    Exact eden;
    Cramer<Exact>(i, j, k, enum_, eden);
    std::pair<double, double> bounds[4];
    for (int c = 0; c < 3; ++c) bounds[c] = CGAL::to_interval(enum_[c]);
    bounds[3] = CGAL::to_interval(eden);
    WithUpwardRounding([&] {
      for (int c = 0; c < 3; ++c) x[c] = Interval(bounds[c]) / Interval(bounds[3]);
      return 0;
    });
  }
  VertexBounds bounds;
  for (int c = 0; c < 3; ++c) {
    bounds.lo[c] = x[c].inf();
    bounds.hi[c] = x[c].sup();
    bounds.approx[c] = 0.5 * (x[c].inf() + x[c].sup());
  }
  return bounds;
}

}  // namespace linesurf::partition
