// The closed forms of Algorithms 1 to 3 against a numerical minimization of the
// exact interpolation error (eq. 2/5) over random stars, volume preservation,
// and the printed coefficients of Algorithm 2.
#include <CGAL/BODT_3/internal/Moves/Bodt_feature_move.h>
#include <CGAL/BODT_3/internal/Moves/Bodt_surface_move.h>
#include <CGAL/BODT_3/internal/Moves/Nodt_move.h>
#include <CGAL/BODT_3/internal/Moves/Odt_interior_move.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Vector = K::Vector_3;
using Star = CGAL::BODT_3::internal::Vertex_star<K>;

namespace {

// ---------------------------------------------------------------------------
// The exact error, computed tetrahedron by tetrahedron in long double, from
// nothing but its definition: for the star of x* with the same connectivity,
//   Error = sum_tau ( |tau| / 4 sum_{v in tau} f(v) - int_tau f ),  f = |x - x0|^2,
// with int_tau f = |tau| / 20 (sum_k |a_k|^2 + |sum_k a_k|^2), a_k = v_k - x0.
// ---------------------------------------------------------------------------
using LD = long double;
struct P3 { LD x, y, z; };

P3 sub(const P3& a, const P3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
LD dot(const P3& a, const P3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
P3 cross(const P3& a, const P3& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
P3 to_p3(const Point& p) { return {p.x(), p.y(), p.z()}; }

LD signed_volume(const P3& p0, const P3& p1, const P3& p2, const P3& p3)
{
  return dot(sub(p1, p0), cross(sub(p2, p0), sub(p3, p0))) / 6;
}

LD tet_error(const P3& x0, const std::array<P3, 4>& v)
{
  const LD vol = signed_volume(v[0], v[1], v[2], v[3]);
  LD sum_f = 0, sum_sq = 0;
  P3 s{0, 0, 0};
  for(const P3& p : v)
  {
    const P3 a = sub(p, x0);
    sum_f += dot(a, a);
    sum_sq += dot(a, a);
    s = {s.x + a.x, s.y + a.y, s.z + a.z};
  }
  return vol / 4 * sum_f - vol / 20 * (sum_sq + dot(s, s));
}

// Exact error of the star of x0 + X, per subdomain when `only` >= 0.
LD exact_error(const Star& star, const P3& X, int only = -1)
{
  const P3 x0 = to_p3(star.x0);
  const P3 xs{x0.x + X.x, x0.y + X.y, x0.z + X.z};
  LD e = 0;
  for(const auto& c : star.cells)
    if(only < 0 || c.subdomain == only) e += tet_error(x0, {xs, to_p3(c.a), to_p3(c.b), to_p3(c.c)});
  return e;
}

LD star_volume(const Star& star, const P3& X, int only = -1)
{
  const P3 x0 = to_p3(star.x0);
  const P3 xs{x0.x + X.x, x0.y + X.y, x0.z + X.z};
  LD v = 0;
  for(const auto& c : star.cells)
    if(only < 0 || c.subdomain == only) v += signed_volume(xs, to_p3(c.a), to_p3(c.b), to_p3(c.c));
  return v;
}

// Newton's method with central finite differences on a function of k <= 3
// coordinates: a numerical minimizer that knows nothing of the closed forms.
std::vector<LD> newton_minimize(const std::function<LD(const std::vector<LD>&)>& f, std::size_t k, LD h)
{
  std::vector<LD> x(k, 0);
  for(int iter = 0; iter < 20; ++iter)
  {
    std::vector<LD> g(k), H(k * k);
    for(std::size_t i = 0; i < k; ++i)
    {
      auto xp = x, xm = x;
      xp[i] += h;
      xm[i] -= h;
      g[i] = (f(xp) - f(xm)) / (2 * h);
      for(std::size_t j = 0; j < k; ++j)
      {
        auto pp = x, pm = x, mp = x, mm = x;
        pp[i] += h; pp[j] += h;
        pm[i] += h; pm[j] -= h;
        mp[i] -= h; mp[j] += h;
        mm[i] -= h; mm[j] -= h;
        H[i * k + j] = (f(pp) - f(pm) - f(mp) + f(mm)) / (4 * h * h);
      }
    }
    // Solve H d = -g by Gaussian elimination (k <= 3).
    std::vector<LD> A = H, b(k);
    for(std::size_t i = 0; i < k; ++i) b[i] = -g[i];
    for(std::size_t c = 0; c < k; ++c)
    {
      std::size_t piv = c;
      for(std::size_t r = c + 1; r < k; ++r)
        if(std::fabs(A[r * k + c]) > std::fabs(A[piv * k + c])) piv = r;
      for(std::size_t j = 0; j < k; ++j) std::swap(A[c * k + j], A[piv * k + j]);
      std::swap(b[c], b[piv]);
      for(std::size_t r = c + 1; r < k; ++r)
      {
        const LD m = A[r * k + c] / A[c * k + c];
        for(std::size_t j = c; j < k; ++j) A[r * k + j] -= m * A[c * k + j];
        b[r] -= m * b[c];
      }
    }
    std::vector<LD> d(k);
    for(std::size_t c = k; c-- > 0;)
    {
      LD s = b[c];
      for(std::size_t j = c + 1; j < k; ++j) s -= A[c * k + j] * d[j];
      d[c] = s / A[c * k + c];
    }
    LD step = 0;
    for(std::size_t i = 0; i < k; ++i)
    {
      x[i] += d[i];
      step = std::max(step, std::fabs(d[i]));
    }
    if(step < 1e-17L) break;
  }
  return x;
}

Vector unit(const Vector& v) { return v / std::sqrt(v.squared_length()); }

std::pair<Vector, Vector> plane_basis(const Vector& normal)
{
  const Vector n = unit(normal);
  const Vector e = std::abs(n.x()) < 0.6 ? Vector(1, 0, 0) : Vector(0, 1, 0);
  const Vector s = unit(e - (e * n) * n);
  return {s, CGAL::cross_product(n, s)};
}

// Adds cell (x0, a, b, c), reordered to be positively oriented.
void add_cell(Star& star, const Point& a, const Point& b, const Point& c, int subdomain = 1)
{
  if(CGAL::orientation(star.x0, a, b, c) == CGAL::POSITIVE)
    star.cells.push_back({a, b, c, subdomain});
  else
    star.cells.push_back({a, c, b, subdomain});
}

bool star_is_valid(const Star& star);

// A star whose link is a disk: a ring y_1..y_m around x0 = origin, roughly in the
// plane z = 0, coned to one or two points below; the boundary facets are
// (x0, y_i, y_{i+1}), counterclockwise seen from above, hence outward.
Star random_boundary_star_candidate(CGAL::Random& rng)
{
  Star star;
  star.x0 = Point(rng.get_double(-0.05, 0.05), rng.get_double(-0.05, 0.05), 0);
  const int m = rng.get_int(4, 11);
  std::vector<double> angles;
  for(int i = 0; i < m; ++i) angles.push_back(2 * CGAL_PI * (i + rng.get_double(0.1, 0.9)) / m);
  std::vector<Point> ring;
  for(double a : angles)
  {
    const double r = rng.get_double(0.6, 1.4);
    ring.emplace_back(r * std::cos(a), r * std::sin(a), rng.get_double(-0.2, 0.2));
  }
  const bool two_apexes = rng.get_bool();
  const Point apex1(rng.get_double(-0.2, 0.2), rng.get_double(-0.2, 0.2), -rng.get_double(0.8, 1.2));
  // With two apexes, ring vertices on the x >= 0 side cone to apex1, the others to
  // apex2, and the triangle (x0, apex1, apex2) closes the gap: the link stays a disk.
  const Point apex2(apex1.x() - 0.3, apex1.y(), apex1.z() - 0.2);
  for(int i = 0; i < m; ++i)
  {
    const Point& yi = ring[i];
    const Point& yj = ring[(i + 1) % m];
    star.boundary.push_back({yi, yj});
    if(!two_apexes)
    {
      add_cell(star, yi, yj, apex1);
      continue;
    }
    const bool si = yi.x() >= 0, sj = yj.x() >= 0;
    if(si && sj) add_cell(star, yi, yj, apex1);
    else if(!si && !sj) add_cell(star, yi, yj, apex2);
    else
    {
      add_cell(star, yi, yj, si ? apex1 : apex2);
      add_cell(star, si ? apex1 : apex2, yj, si ? apex2 : apex1);
    }
  }
  return star;
}

// Random geometry can fold a cell over: draw again until the star is valid.
Star random_boundary_star(CGAL::Random& rng)
{
  for(;;)
  {
    Star star = random_boundary_star_candidate(rng);
    if(star_is_valid(star)) return star;
  }
}

// An inner star: x0 near the centre of a random star-shaped polytope, here the
// boundary of a perturbed octahedron subdivided once.
Star random_inner_star(CGAL::Random& rng)
{
  Star star;
  star.x0 = Point(rng.get_double(-0.1, 0.1), rng.get_double(-0.1, 0.1), rng.get_double(-0.1, 0.1));
  auto jitter = [&](double x, double y, double z) {
    const double r = rng.get_double(0.7, 1.3);
    const double l = std::sqrt(x * x + y * y + z * z);
    return Point(r * x / l, r * y / l, r * z / l);
  };
  const Point top = jitter(0, 0, 1), bottom = jitter(0, 0, -1);
  std::vector<Point> equator;
  const int m = rng.get_int(4, 9);
  for(int i = 0; i < m; ++i)
  {
    const double a = 2 * CGAL_PI * (i + rng.get_double(0.2, 0.8)) / m;
    equator.push_back(jitter(std::cos(a), std::sin(a), rng.get_double(-0.3, 0.3)));
  }
  for(int i = 0; i < m; ++i)
  {
    add_cell(star, equator[i], equator[(i + 1) % m], top);
    add_cell(star, equator[i], equator[(i + 1) % m], bottom);
  }
  return star;
}

// Every cell positively oriented, and the link (the faces opposite x0) a
// consistently oriented surface whose rim is exactly the ring of boundary facets.
bool star_is_valid(const Star& star)
{
  using Key = std::array<double, 6>;
  auto key = [](const Point& u, const Point& v) { return Key{u.x(), u.y(), u.z(), v.x(), v.y(), v.z()}; };
  std::map<Key, int> edges;
  for(const auto& c : star.cells)
  {
    if(CGAL::orientation(star.x0, c.a, c.b, c.c) != CGAL::POSITIVE) return false;
    ++edges[key(c.a, c.b)];
    ++edges[key(c.b, c.c)];
    ++edges[key(c.c, c.a)];
  }
  std::size_t rim = 0;
  for(const auto& e : edges)
  {
    if(e.second != 1) return false;
    const Key reverse{e.first[3], e.first[4], e.first[5], e.first[0], e.first[1], e.first[2]};
    if(edges.count(reverse)) continue;
    // An unpaired link edge (u, v) bounds the link: it is the boundary facet (x0, v, u).
    bool found = false;
    for(const auto& f : star.boundary)
      found = found || key(f.b, f.a) == e.first;
    if(!found) return false;
    ++rim;
  }
  return rim == star.boundary.size();
}

LD norm(const P3& p) { return std::sqrt(dot(p, p)); }
P3 to_p3(const Vector& v) { return {v.x(), v.y(), v.z()}; }

} // namespace

TEST(OdtMove, RegularStarMovesBackToTheCentre)
{
  // Regular octahedron around the origin; x0 displaced: the optimum is the centre.
  Star star;
  star.x0 = Point(0.1, -0.05, 0.03);
  const Point v[6] = {Point(1, 0, 0), Point(-1, 0, 0), Point(0, 1, 0), Point(0, -1, 0), Point(0, 0, 1), Point(0, 0, -1)};
  for(int a : {0, 1})
    for(int b : {2, 3})
      for(int c : {4, 5}) add_cell(star, v[a], v[b], v[c]);
  const Vector X = CGAL::BODT_3::internal::Odt_interior_move()(star);
  EXPECT_NEAR(X.x(), -0.1, 1e-14);
  EXPECT_NEAR(X.y(), 0.05, 1e-14);
  EXPECT_NEAR(X.z(), -0.03, 1e-14);
}

TEST(OdtMove, EqualsNumericalMinimizerOnRandomInnerStars)
{
  CGAL::Random rng(11);
  for(int n = 0; n < 200; ++n)
  {
    const Star star = random_inner_star(rng);
    ASSERT_TRUE(star_is_valid(star));
    const Vector X = CGAL::BODT_3::internal::Odt_interior_move()(star);
    const auto num = newton_minimize(
        [&](const std::vector<LD>& x) { return exact_error(star, {x[0], x[1], x[2]}); }, 3, 1e-3L);
    const P3 d{num[0] - X.x(), num[1] - X.y(), num[2] - X.z()};
    EXPECT_LE(norm(d), 1e-8 * norm({num[0], num[1], num[2]})) << "star " << n;
    EXPECT_LT(exact_error(star, to_p3(X)), exact_error(star, {0, 0, 0}) + 1e-15L);
  }
}

TEST(BodtSurfaceMove, EqualsNumericalMinimizerOnRandomBoundaryStars)
{
  CGAL::Random rng(5);
  int moved = 0;
  for(int n = 0; n < 300; ++n)
  {
    const Star star = random_boundary_star(rng);
    ASSERT_TRUE(star_is_valid(star)) << "star " << n;
    const Vector normal = star.boundary_normal();
    // (B.4): the (B.1) normal equals sum_tau S_tau n_tau over the cells.
    const Vector from_cells = star.subdomain_normal(1);
    EXPECT_LE(std::sqrt((normal - from_cells).squared_length()), 1e-14 * std::sqrt(normal.squared_length()));

    const Vector X = CGAL::BODT_3::internal::Bodt_surface_move()(star, normal);
    const auto st = plane_basis(normal);
    auto on_plane = [&](const std::vector<LD>& x) {
      return P3{x[0] * st.first.x() + x[1] * st.second.x(), x[0] * st.first.y() + x[1] * st.second.y(),
                x[0] * st.first.z() + x[1] * st.second.z()};
    };
    const auto num = newton_minimize([&](const std::vector<LD>& x) { return exact_error(star, on_plane(x)); }, 2,
                                     1e-3L);
    const P3 Xn = on_plane(num);
    const P3 d = sub(Xn, to_p3(X));
    EXPECT_LE(norm(d), 1e-8 * norm(Xn)) << "star " << n;
    // The move stays on the tangent plane and keeps the star's volume.
    EXPECT_LE(std::abs(X * unit(normal)), 1e-15);
    const LD v0 = star_volume(star, {0, 0, 0});
    EXPECT_LE(std::fabs(star_volume(star, to_p3(X)) - v0), 1e-13L * v0) << "star " << n;
    if(norm(to_p3(X)) > 0) ++moved;
  }
  EXPECT_EQ(moved, 300);
}

// NODT, unconstrained: one Newton step from X = 0 on the exact error (which is
// cubic off the tangent plane), with derivatives by central differences.
TEST(NodtMove, IsTheNewtonStepOfTheExactError)
{
  CGAL::Random rng(17);
  int moved = 0;
  for(int n = 0; n < 200; ++n)
  {
    const Star star = random_boundary_star(rng);
    const Vector X = CGAL::BODT_3::internal::Nodt_move()(star);
    const LD h = 1e-4L;
    auto f = [&](LD a, LD b, LD c) { return exact_error(star, {a, b, c}); };
    LD g[3], H[3][3];
    for(int i = 0; i < 3; ++i)
    {
      LD e[3] = {0, 0, 0};
      e[i] = h;
      g[i] = (f(e[0], e[1], e[2]) - f(-e[0], -e[1], -e[2])) / (2 * h);
      for(int j = 0; j < 3; ++j)
      {
        LD d[3] = {0, 0, 0};
        d[j] = h;
        H[i][j] = (f(e[0] + d[0], e[1] + d[1], e[2] + d[2]) - f(e[0] - d[0], e[1] - d[1], e[2] - d[2]) -
                   f(-e[0] + d[0], -e[1] + d[1], -e[2] + d[2]) + f(-e[0] - d[0], -e[1] - d[1], -e[2] - d[2])) /
                  (4 * h * h);
      }
    }
    // Solve H X = -g (Cramer) and compare.
    auto det3 = [](LD m[3][3]) {
      return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
             m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    };
    const LD det = det3(H);
    if(!(det > 0) || !(H[0][0] > 0)) continue;
    P3 num;
    LD* out[3] = {&num.x, &num.y, &num.z};
    for(int k = 0; k < 3; ++k)
    {
      LD m[3][3];
      for(int i = 0; i < 3; ++i)
        for(int j = 0; j < 3; ++j) m[i][j] = j == k ? -g[i] : H[i][j];
      *out[k] = det3(m) / det;
    }
    EXPECT_LE(norm(sub(num, to_p3(X))), 1e-6 * norm(num)) << "star " << n;
    if(norm(to_p3(X)) > 0) ++moved;
  }
  EXPECT_GT(moved, 150);
  // Inside, NODT is ODT.
  for(int n = 0; n < 50; ++n)
  {
    const Star star = random_inner_star(rng);
    const Vector a = CGAL::BODT_3::internal::Nodt_move()(star), b = CGAL::BODT_3::internal::Odt_interior_move()(star);
    EXPECT_LE(std::sqrt((a - b).squared_length()), 1e-12 * std::sqrt(b.squared_length())) << "star " << n;
  }
}

TEST(BodtSurfaceMove, CoefficientsAreThePrintedOnes)
{
  // Algorithm 2 as printed (with F using Y_i x Y_{i+1}), term by term.
  CGAL::Random rng(3);
  for(int n = 0; n < 50; ++n)
  {
    const Star star = random_boundary_star(rng);
    const auto st = plane_basis(star.boundary_normal());
    const Vector s = st.first, t = st.second;
    double vol = 0;
    Vector sum_snl(0, 0, 0);
    for(const auto& c : star.cells)
    {
      const Vector a = c.a - star.x0, b = c.b - star.x0, cc = c.c - star.x0;
      vol += CGAL::determinant(a, b, cc) / 6;
      const double L = a.squared_length() + b.squared_length() + cc.squared_length();
      const Vector n_towards_x0 = -0.5 * CGAL::cross_product(b - a, cc - a);   // S_tau n_tau
      sum_snl = sum_snl + L * n_towards_x0;
    }
    double E = vol / 4, F = vol / 4, G = 0, H = s * sum_snl / 12, I = t * sum_snl / 12;
    for(const auto& f : star.boundary)
    {
      const Vector Yi = f.a - star.x0, Yj = f.b - star.x0, w = CGAL::cross_product(Yi, Yj);
      E -= (s * (Yi + Yj)) * (s * w) / 60;
      F -= (t * (Yi + Yj)) * (t * w) / 60;
      G -= ((s * (Yi + Yj)) * (t * w) + (t * (Yi + Yj)) * (s * w)) / 60;
      const double r = Yi.squared_length() + Yj.squared_length() + Yi * Yj;
      H -= r * (s * w) / 60;
      I -= r * (t * w) / 60;
    }
    const CGAL::BODT_3::internal::Interpolation_error<K> model(star);
    EXPECT_NEAR(model.quadratic(s, s), E, 1e-13);
    EXPECT_NEAR(model.quadratic(t, t), F, 1e-13);
    EXPECT_NEAR(2 * model.quadratic(s, t), G, 1e-13);
    EXPECT_NEAR(model.linear(s), H, 1e-13);
    EXPECT_NEAR(model.linear(t), I, 1e-13);
    EXPECT_GT(4 * E * F - G * G, 0);
  }
}

TEST(BodtFeatureMove, EqualsNumericalMinimizerAlongTheFeature)
{
  CGAL::Random rng(9);
  for(int n = 0; n < 300; ++n)
  {
    const Star star = random_boundary_star(rng);
    ASSERT_TRUE(star_is_valid(star));
    const Vector normal = unit(star.boundary_normal());
    Vector d(rng.get_double(-1, 1), rng.get_double(-1, 1), rng.get_double(-1, 1));
    d = unit(d - (d * normal) * normal);
    const Vector X = CGAL::BODT_3::internal::Bodt_feature_move()(star, d);
    const auto num = newton_minimize(
        [&](const std::vector<LD>& x) { return exact_error(star, {x[0] * d.x(), x[0] * d.y(), x[0] * d.z()}); }, 1,
        1e-3L);
    const P3 Xn{num[0] * d.x(), num[0] * d.y(), num[0] * d.z()};
    EXPECT_LE(norm(sub(Xn, to_p3(X))), 1e-8 * norm(Xn)) << "star " << n;
    const LD v0 = star_volume(star, {0, 0, 0});
    EXPECT_LE(std::fabs(star_volume(star, to_p3(X)) - v0), 1e-13L * v0);
  }
}

TEST(BodtSurfaceMove, InterfaceVertexKeepsEverySubdomainVolume)
{
  // An inner star split into two subdomains by the side of each cell's centroid:
  // the vertex moves on the interface's tangent plane and minimizes the total error.
  CGAL::Random rng(21);
  for(int n = 0; n < 200; ++n)
  {
    Star star = random_inner_star(rng);
    for(auto& c : star.cells)
      c.subdomain = (c.a.z() + c.b.z() + c.c.z() > 0) ? 2 : 1;
    const Vector n1 = star.subdomain_normal(1), n2 = star.subdomain_normal(2);
    ASSERT_LE(std::sqrt((n1 + n2).squared_length()), 1e-14 * std::sqrt(n1.squared_length()));
    const Vector X = CGAL::BODT_3::internal::Bodt_surface_move()(star, n1);
    const auto st = plane_basis(n1);
    auto on_plane = [&](const std::vector<LD>& x) {
      return P3{x[0] * st.first.x() + x[1] * st.second.x(), x[0] * st.first.y() + x[1] * st.second.y(),
                x[0] * st.first.z() + x[1] * st.second.z()};
    };
    const auto num = newton_minimize([&](const std::vector<LD>& x) { return exact_error(star, on_plane(x)); }, 2,
                                     1e-3L);
    EXPECT_LE(norm(sub(on_plane(num), to_p3(X))), 1e-8 * norm(on_plane(num))) << "star " << n;
    for(int sd : {1, 2})
    {
      const LD v0 = star_volume(star, {0, 0, 0}, sd);
      EXPECT_LE(std::fabs(star_volume(star, to_p3(X), sd) - v0), 1e-13L * v0) << "star " << n;
    }
  }
}

TEST(BodtSurfaceMove, NoMoveWithoutAUniqueMinimum)
{
  // A star of zero volume has E = 0: 4EF > G^2 fails, the vertex stays.
  Star star;
  star.x0 = Point(0, 0, 0);
  star.boundary.push_back({Point(1, 0, 0), Point(0, 1, 0)});
  const Vector X = CGAL::BODT_3::internal::Bodt_surface_move()(star, Vector(0, 0, 1));
  EXPECT_EQ(X, Vector(0, 0, 0));
  EXPECT_EQ(CGAL::BODT_3::internal::Bodt_feature_move()(star, Vector(1, 0, 0)), Vector(0, 0, 0));
  EXPECT_EQ(CGAL::BODT_3::internal::Odt_interior_move()(star), Vector(0, 0, 0));
}
