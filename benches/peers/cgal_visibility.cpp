// cgal_visibility: CGAL's triangular-expansion visibility polygon as an
// independent oracle and speed peer for wai (see benches/peers/README.md).
//
// Build: benches/peers/build.sh (g++ -O2 -std=c++17 -DNDEBUG, CGAL 5.5.1
// header-only, GMP + MPFR). Kernel: CGAL::Exact_predicates_exact_constructions_kernel
// (Epeck). Its FT is Lazy_exact_nt<ET>; with Debian's headers and plain g++
// (no CMake, so no CGAL_USE_GMPXX; Boost present, so CGAL_USE_BOOST_MP), ET is
// boost::multiprecision::mpq_rational, i.e. a GMP mpq_t. The code also works
// with CGAL::Gmpq and mpq_class.
//
// PROTOCOL (stdin, whitespace separated tokens; one reply line per command
// on stdout, flushed). A rational is `p/q` or an integer `p`.
//   polygon N x1 y1 ... xN yN   simple polygon, counter-clockwise, no holes.
//                               Builds the arrangement and the visibility
//                               object (the constrained triangulation).
//                               Reply: `ok N`.
//   holed N x1 y1 ... xN yN H M1 x y ... M2 x y ...
//                               a polygon with H holes: the outer ring
//                               counter-clockwise, each hole (M vertices)
//                               clockwise. Reply: `ok T`, T every vertex.
//   query x y                   q strictly inside the polygon. Reply:
//                               `vis K x1 y1 ... xK yK`, counter-clockwise,
//                               starting at the lexicographically (x, then y)
//                               smallest vertex, every coordinate printed as
//                               the reduced rational `p/q` (q >= 1, always
//                               with the slash, also for integers: `3/1`).
//   bench R x y                 the same query R times; reply
//                               `time_ns M`, M the median (of R single
//                               timings, steady_clock) of compute_visibility
//                               alone: it excludes preprocessing, the point
//                               location of q (done once, before timing) and
//                               the exact evaluation of constructed
//                               coordinates (Epeck is lazy: compute_visibility
//                               only builds interval approximations of the
//                               ray/edge intersection points).
//   bench_exact R x y           as bench, but each timing also walks the
//                               output face and forces the exact (GMP mpq) value
//                               of every vertex coordinate: the time to obtain
//                               the exact polygon.
//   quit                        exit 0 (end of input does the same).
//   # ...                       a comment, to the end of the line (no reply).
// Errors: `error <message>`. Semantic errors (non-simple or clockwise
// polygon, q not strictly inside, no polygon yet) keep the program running;
// a malformed token (unknown command, bad number) desynchronises the token
// stream, so the program prints the error and exits with status 2.
//
// REGULARIZATION: Triangular_expansion_visibility_2<Arrangement_2, CGAL::Tag_true>.
// Tag_true means "regularized": the result is the closure of the interior of
// the visible set. With Tag_false CGAL also reports needles (antennas): the
// zero-width segments seen when q is collinear with a boundary edge / a
// pair of vertices and the ray continues past a vertex along the boundary.
// Those are part of the (non-closed) visible set, but they are not part of
// the visibility *polygon* the thesis and wai use, so Tag_true is the right
// oracle. (In CGAL 5.5.1 Tag_true simply never collects needles; see
// Triangular_expansion_visibility_2.h, `if(!Regularization_category::value)`.)
//
// OBSERVED CONVENTIONS (CGAL 5.5.1, Tag_true; inputs benches/peers/conventions.txt,
// replies conventions.expected, discussion README.md):
//  * Orientation: the output face's outer CCB is counter-clockwise (the
//    arrangement convention); reply_vis checks the sign of the area exactly.
//  * Collinear consecutive vertices DO occur. Every map vertex that the
//    expansion meets on a straight stretch of the boundary of V(q) is
//    reported: (a) q on the line of map edges: comb, q = (1/2, 2) gives
//    (10,2) (9,2) (7,2) (6,2) (4,2) (3,2) (1,2) in a row; (b) a window that
//    passes through several reflex vertices: spikes with tips (2,2), (3,3),
//    q = (1,1) gives (10,10) (3,3) (2,2) in a row. Points of V(q) that are
//    not map vertices (ray hits) are reported only where the boundary turns.
//  * No duplicates: no vertex is repeated (consecutively or not) on any test
//    or on the AGPLIB / generated maps we ran (a window ending exactly at a
//    map vertex, L room q = (3,1) -> (2,2) (0,4), reports that vertex once).
//  * No needles: none with Tag_true, also when q is on the line of a map edge
//    or of two map vertices. (Tag_false gave byte-identical replies on every
//    test of conventions.txt, including two where the closed visible set has
//    a needle, so CGAL 5.5.1's Tag_false does not report those either.)
//  * Start vertex: chosen here (lexicographically smallest), not by CGAL.

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Arr_naive_point_location.h>
#include <CGAL/Triangular_expansion_visibility_2.h>
#include <CGAL/Polygon_2.h>
#include <gmp.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

typedef CGAL::Exact_predicates_exact_constructions_kernel Kernel;
typedef Kernel::FT FT;
typedef Kernel::Point_2 Point_2;
typedef Kernel::Segment_2 Segment_2;
typedef CGAL::Arr_segment_traits_2<Kernel> Traits_2;
typedef CGAL::Arrangement_2<Traits_2> Arrangement_2;
typedef Arrangement_2::Face_const_handle Face_const_handle;
typedef Arrangement_2::Face_handle Face_handle;
typedef Arrangement_2::Halfedge_const_handle Halfedge_const_handle;
typedef Arrangement_2::Vertex_const_handle Vertex_const_handle;
typedef Arrangement_2::Ccb_halfedge_const_circulator Ccb_circulator;
typedef CGAL::Arr_naive_point_location<Arrangement_2> Naive_pl;
// Regularized: the closure of the visible region, no needles (see above).
typedef CGAL::Triangular_expansion_visibility_2<Arrangement_2, CGAL::Tag_true> TEV;
typedef CGAL::Polygon_2<Kernel> Polygon_2;

// The exact number type behind Epeck's lazy FT (mpq_rational here).
typedef std::decay_t<decltype(CGAL::exact(std::declval<FT>()))> ET;

namespace {

// A malformed token: the token stream cannot be trusted any more.
struct Fatal : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// RAII mpq_t.
struct Mpq {
  mpq_t v;
  Mpq() { mpq_init(v); }
  ~Mpq() { mpq_clear(v); }
  Mpq(const Mpq&) = delete;
  Mpq& operator=(const Mpq&) = delete;
};

std::string mpz_text(mpz_srcptr z) {
  std::unique_ptr<char[]> buf(new char[mpz_sizeinbase(z, 10) + 2]);
  mpz_get_str(buf.get(), 10, z);
  return std::string(buf.get());
}

// ET <-> mpq_t. ET is boost::multiprecision::mpq_rational (GMP backend) with
// the Debian headers (CGAL_USE_BOOST_MP is on when Boost is found); Gmpq or
// mpq_class with other configurations.
// (Templates, so that `if constexpr` discards the branches of other types.)
template <class E>
mpq_srcptr et_mpq(const E& e) {
  if constexpr (std::is_same_v<E, CGAL::Gmpq>) {
    return e.mpq();
  } else if constexpr (std::is_same_v<E, boost::multiprecision::mpq_rational>) {
    return e.backend().data();
  } else {
    return e.get_mpq_t();  // mpq_class
  }
}

template <class E = ET>
E et_from_mpq(mpq_srcptr q) {
  if constexpr (std::is_same_v<E, CGAL::Gmpq>) {
    return CGAL::Gmpq(q);
  } else if constexpr (std::is_same_v<E, boost::multiprecision::mpq_rational>) {
    E e;
    mpq_set(e.backend().data(), q);
    return e;
  } else {
    return E(q);  // mpq_class
  }
}

std::string et_text(const ET& e) {
  Mpq q;
  mpq_set(q.v, et_mpq(e));
  mpq_canonicalize(q.v);
  return mpz_text(mpq_numref(q.v)) + "/" + mpz_text(mpq_denref(q.v));
}

// A cheap function of an exact value, so its computation is not optimised out.
std::size_t et_size(const ET& e) { return mpz_size(mpq_numref(et_mpq(e))); }

// `p/q` or `p`, decimal, optional leading '-'; q > 0 after canonicalisation.
FT parse_rational(const std::string& tok) {
  bool ok = !tok.empty();
  std::size_t slashes = 0;
  for (std::size_t i = 0; ok && i < tok.size(); ++i) {
    char c = tok[i];
    if (c == '/') {
      ++slashes;
      ok = slashes == 1 && i > 0 && i + 1 < tok.size() && tok[i - 1] != '-';
    } else if (c == '-') {
      ok = i == 0 || tok[i - 1] == '/';
    } else {
      ok = c >= '0' && c <= '9';
    }
  }
  Mpq q;
  if (!ok || mpq_set_str(q.v, tok.c_str(), 10) != 0) {
    throw Fatal("bad rational '" + tok + "'");
  }
  if (mpz_sgn(mpq_denref(q.v)) == 0) {
    throw Fatal("zero denominator in '" + tok + "'");
  }
  mpq_canonicalize(q.v);
  return FT(et_from_mpq(q.v));
}

std::string next_token(std::istream& in, const char* what) {
  std::string tok;
  if (!(in >> tok)) {
    throw Fatal(std::string("unexpected end of input, expected ") + what);
  }
  return tok;
}

long long parse_count(const std::string& tok, const char* what) {
  if (tok.empty() || tok.size() > 12 ||
      !std::all_of(tok.begin(), tok.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    throw Fatal(std::string("bad ") + what + " '" + tok + "'");
  }
  return std::stoll(tok);
}

Point_2 read_point(std::istream& in) {
  FT x = parse_rational(next_token(in, "x"));
  FT y = parse_rational(next_token(in, "y"));
  return Point_2(x, y);
}

// A semantic error: reported, the session goes on.
struct Soft : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class Session {
 public:
  void set_polygon(std::vector<Point_2> pts) { set_domain(std::move(pts), {}); }

  // A polygon with holes: the outer ring counter-clockwise, each hole
  // clockwise; the free face is the bounded face with one inner boundary
  // per hole.
  void set_domain(std::vector<Point_2> pts, std::vector<std::vector<Point_2>> holes) {
    // Tear down in dependency order: the visibility object observes arr.
    tev_.reset();
    pl_.reset();
    arr_.reset();
    if (pts.size() < 3) throw Soft("polygon needs at least 3 vertices");
    Polygon_2 poly(pts.begin(), pts.end());
    if (!poly.is_simple()) throw Soft("polygon is not simple");
    if (poly.orientation() != CGAL::COUNTERCLOCKWISE) throw Soft("polygon is not counter-clockwise");
    std::size_t total = pts.size();
    std::vector<Segment_2> segs;
    segs.reserve(pts.size());
    auto ring = [&segs](const std::vector<Point_2>& r) {
      for (std::size_t i = 0; i < r.size(); ++i) segs.emplace_back(r[i], r[(i + 1) % r.size()]);
    };
    ring(pts);
    for (const auto& h : holes) {
      if (h.size() < 3) throw Soft("hole needs at least 3 vertices");
      Polygon_2 hp(h.begin(), h.end());
      if (!hp.is_simple()) throw Soft("hole is not simple");
      if (hp.orientation() != CGAL::CLOCKWISE) throw Soft("hole is not clockwise");
      ring(h);
      total += h.size();
    }
    auto arr = std::make_unique<Arrangement_2>();
    CGAL::insert_non_intersecting_curves(*arr, segs.begin(), segs.end());
    if (arr->number_of_faces() != 2 + holes.size() || arr->number_of_edges() != total) {
      throw Soft("arrangement is not one bounded face with its holes");
    }
    bool found = false;
    for (auto f = arr->faces_begin(); f != arr->faces_end(); ++f) {
      if (!f->is_unbounded() && f->number_of_holes() == holes.size()) {
        if (found && !holes.empty()) throw Soft("two faces could be the free space");
        free_ = f;
        found = true;
        if (holes.empty()) break;
      }
    }
    if (!found) throw Soft("no face has every hole inside it");
    arr_ = std::move(arr);
    pl_ = std::make_unique<Naive_pl>(*arr_);
    tev_ = std::make_unique<TEV>(*arr_);  // builds the constrained triangulation
    n_ = total;
  }

  std::size_t n() const { return n_; }

  // The bounded face containing q in its interior.
  Face_const_handle locate(const Point_2& q) const {
    if (!arr_) throw Soft("no polygon");
    auto obj = pl_->locate(q);
    if (const Face_const_handle* f = boost::get<Face_const_handle>(&obj)) {
      if ((*f)->is_unbounded()) throw Soft("query point outside the polygon");
      if (*f != free_) throw Soft("query point inside a hole");
      return *f;
    }
    if (boost::get<Halfedge_const_handle>(&obj)) throw Soft("query point on a polygon edge");
    if (boost::get<Vertex_const_handle>(&obj)) throw Soft("query point on a polygon vertex");
    throw Soft("point location failed");
  }

  Face_handle visibility(const Point_2& q, Face_const_handle f, Arrangement_2& out) const {
    return tev_->compute_visibility(q, f, out);
  }

 private:
  std::unique_ptr<Arrangement_2> arr_;
  std::unique_ptr<Naive_pl> pl_;
  std::unique_ptr<TEV> tev_;
  Face_const_handle free_;
  std::size_t n_ = 0;
};

// The output face's boundary, CCW, rotated to start at the xy-smallest vertex.
std::vector<Point_2> face_ring(Face_handle fh) {
  std::vector<Point_2> ring;
  if (fh->is_unbounded() || !fh->has_outer_ccb()) throw Soft("visibility face is unbounded");
  if (fh->number_of_holes() != 0) throw Soft("visibility face has holes");
  Ccb_circulator first = fh->outer_ccb(), c = first;
  do {
    ring.push_back(c->source()->point());
  } while (++c != first);
  std::size_t best = 0;
  for (std::size_t i = 1; i < ring.size(); ++i) {
    if (CGAL::compare_xy(ring[i], ring[best]) == CGAL::SMALLER) best = i;
  }
  std::rotate(ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(best), ring.end());
  return ring;
}

void reply_vis(const std::vector<Point_2>& ring) {
  // Sanity: positive area (CCW), exactly.
  FT area2 = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point_2& a = ring[i];
    const Point_2& b = ring[(i + 1) % ring.size()];
    area2 += a.x() * b.y() - a.y() * b.x();
  }
  if (CGAL::sign(area2) != CGAL::POSITIVE) throw Soft("visibility polygon is not counter-clockwise");
  std::ostringstream out;
  out << "vis " << ring.size();
  for (const Point_2& p : ring) {
    out << ' ' << et_text(CGAL::exact(p.x())) << ' ' << et_text(CGAL::exact(p.y()));
  }
  std::cout << out.str() << '\n' << std::flush;
}

std::uint64_t median(std::vector<std::uint64_t> t) {
  std::sort(t.begin(), t.end());
  std::size_t m = t.size() / 2;
  if (t.size() % 2 == 1) return t[m];
  return t[m - 1] + (t[m] - t[m - 1]) / 2;
}

std::uint64_t bench(Session& s, long long reps, const Point_2& q, bool exact) {
  if (reps < 1) throw Soft("bench needs R >= 1");
  Face_const_handle f = s.locate(q);
  std::vector<std::uint64_t> times;
  times.reserve(static_cast<std::size_t>(reps));
  std::size_t sink = 0;
  for (long long r = 0; r < reps; ++r) {
    Arrangement_2 out;
    auto t0 = std::chrono::steady_clock::now();
    Face_handle fh = s.visibility(q, f, out);
    if (exact) {
      Ccb_circulator first = fh->outer_ccb(), c = first;
      do {
        const Point_2& p = c->source()->point();
        sink += et_size(CGAL::exact(p.x())) + et_size(CGAL::exact(p.y()));
      } while (++c != first);
    }
    auto t1 = std::chrono::steady_clock::now();
    sink += out.number_of_vertices();
    times.push_back(static_cast<std::uint64_t>(
        std::chrono::duration_cast<std::chrono::nanoseconds>(t1 - t0).count()));
  }
  if (sink == 0) std::cerr << "";  // keep the work observable
  return median(std::move(times));
}

}  // namespace

int main() {
  std::ios::sync_with_stdio(false);
  Session session;
  std::string cmd;
  while (std::cin >> cmd) {
    try {
      if (cmd[0] == '#') {
        std::string rest;
        std::getline(std::cin, rest);  // a comment, to the end of the line
      } else if (cmd == "quit") {
        return 0;
      } else if (cmd == "polygon") {
        long long n = parse_count(next_token(std::cin, "N"), "vertex count");
        std::vector<Point_2> pts;
        pts.reserve(static_cast<std::size_t>(n));
        for (long long i = 0; i < n; ++i) pts.push_back(read_point(std::cin));
        session.set_polygon(std::move(pts));
        std::cout << "ok " << session.n() << '\n' << std::flush;
      } else if (cmd == "holed") {
        long long n = parse_count(next_token(std::cin, "N"), "vertex count");
        std::vector<Point_2> pts;
        pts.reserve(static_cast<std::size_t>(n));
        for (long long i = 0; i < n; ++i) pts.push_back(read_point(std::cin));
        long long h = parse_count(next_token(std::cin, "H"), "hole count");
        std::vector<std::vector<Point_2>> holes(static_cast<std::size_t>(h));
        for (auto& hole : holes) {
          long long m = parse_count(next_token(std::cin, "M"), "hole vertex count");
          for (long long i = 0; i < m; ++i) hole.push_back(read_point(std::cin));
        }
        session.set_domain(std::move(pts), std::move(holes));
        std::cout << "ok " << session.n() << '\n' << std::flush;
      } else if (cmd == "query") {
        Point_2 q = read_point(std::cin);
        Face_const_handle f = session.locate(q);
        Arrangement_2 out;
        Face_handle fh = session.visibility(q, f, out);
        reply_vis(face_ring(fh));
      } else if (cmd == "bench" || cmd == "bench_exact") {
        long long reps = parse_count(next_token(std::cin, "R"), "repetition count");
        Point_2 q = read_point(std::cin);
        std::cout << "time_ns " << bench(session, reps, q, cmd == "bench_exact") << '\n'
                  << std::flush;
      } else {
        throw Fatal("unknown command '" + cmd + "'");
      }
    } catch (const Fatal& e) {
      std::cout << "error " << e.what() << '\n' << std::flush;
      return 2;
    } catch (const Soft& e) {
      std::cout << "error " << e.what() << '\n' << std::flush;
    } catch (const std::exception& e) {
      // CGAL failures (assertions are off under NDEBUG, but CGAL may throw).
      std::cout << "error cgal: " << e.what() << '\n' << std::flush;
    }
  }
  return 0;
}
