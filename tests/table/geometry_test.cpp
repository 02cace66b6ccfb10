// Table geometry: rails, jaw facings, holes and mesh parts from a spec; the committed OBJ files;
// the round trip through assimp.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

#include "table/table_geometry.h"
#include "table/table_spec.h"

namespace pool::table {
namespace {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;

/// The shipped tables with pockets (pool and snooker), and every shipped table.
const std::vector<std::string> kTables{"wpa-9ft", "wpa-8ft", "wpa-7ft", "snooker-12ft"};
const std::vector<std::string> kAllTables{"wpa-9ft", "wpa-8ft", "wpa-7ft", "snooker-12ft",
                                          "carom-match"};
const std::vector<std::string> kRails{"head",      "foot",       "head_left",
                                      "foot_left", "head_right", "foot_right"};
const std::vector<std::string> kPockets{"head_left_corner",  "left_side",  "foot_left_corner",
                                        "head_right_corner", "right_side", "foot_right_corner"};

TableSpec spec(const std::string& name) {
  auto s = loadTableSpec(name);
  EXPECT_TRUE(s) << s.error();
  return *s;
}

std::vector<NoseSegment> nosesNamed(const TableGeometry& g, const std::string& name) {
  std::vector<NoseSegment> out;
  for (const NoseSegment& n : g.noses) {
    if (n.name == name) out.push_back(n);
  }
  return out;
}

const PocketHole& hole(const TableGeometry& g, const std::string& name) {
  for (const PocketHole& h : g.holes) {
    if (h.name == name) return h;
  }
  throw std::runtime_error("no hole " + name);
}

const MeshPart* part(const TableGeometry& g, const std::string& name) {
  for (const MeshPart& p : g.parts) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

/// The corner where two rail nose lines meet, or the side pocket's point on the nose line.
Vec2 pocketReference(const TableSpec& s, const std::string& pocket) {
  const double x = pocket.starts_with("head")   ? -s.length / 2.0
                   : pocket.starts_with("foot") ? s.length / 2.0
                                                : 0.0;
  const double y = pocket.find("left") != std::string::npos ? s.width / 2.0 : -s.width / 2.0;
  return {x, y};
}

/// A facing's jaw point (shared with a rail's end), the rail that ends there and the facing's far
/// end.
struct Facing {
  Vec2 point, far, rail_other_end;
  NoseSegment segment;
};

std::vector<Facing> facingsOf(const TableGeometry& g, const std::string& pocket) {
  std::vector<Facing> out;
  for (const NoseSegment& f : nosesNamed(g, "jaw_" + pocket)) {
    for (const std::string& rail : kRails) {
      const NoseSegment r = nosesNamed(g, rail).at(0);
      for (const auto& [p, q] : {std::pair{f.a, f.b}, std::pair{f.b, f.a}}) {
        if ((p - r.a).norm() < 1e-12) out.push_back({p, q, r.b, f});
        if ((p - r.b).norm() < 1e-12) out.push_back({p, q, r.a, f});
      }
    }
  }
  return out;
}

double angleDeg(const Vec2& u, const Vec2& v) {
  return std::acos(std::clamp(u.normalized().dot(v.normalized()), -1.0, 1.0)) * 180.0 /
         std::numbers::pi;
}

TEST(TableGeometry, HasSixRailsAndTwelveFacings) {
  const TableGeometry g = buildTableGeometry(spec("wpa-9ft"));
  ASSERT_EQ(g.noses.size(), 18u);
  std::map<std::string, int> count;
  for (const NoseSegment& n : g.noses) ++count[n.name];
  for (const std::string& r : kRails) EXPECT_EQ(count[r], 1) << r;
  for (const std::string& p : kPockets) EXPECT_EQ(count["jaw_" + p], 2) << p;
  EXPECT_EQ(count.size(), 12u);
}

TEST(TableGeometry, RailsLieOnThePlayingSurfaceEdges) {
  for (const std::string& name : kTables) {
    const TableSpec s = spec(name);
    const TableGeometry g = buildTableGeometry(s);
    const double hl = s.length / 2.0, hw = s.width / 2.0;
    EXPECT_DOUBLE_EQ(nosesNamed(g, "head")[0].a.x(), -hl);
    EXPECT_DOUBLE_EQ(nosesNamed(g, "foot")[0].b.x(), hl);
    for (const char* r : {"head_left", "foot_left"})
      EXPECT_DOUBLE_EQ(nosesNamed(g, r)[0].a.y(), hw) << r;
    for (const char* r : {"head_right", "foot_right"})
      EXPECT_DOUBLE_EQ(nosesNamed(g, r)[0].a.y(), -hw) << r;
    for (const char* r : {"head_left", "head_right"}) {
      EXPECT_LT(std::max(nosesNamed(g, r)[0].a.x(), nosesNamed(g, r)[0].b.x()), 0.0) << r;
    }
    for (const char* r : {"foot_left", "foot_right"}) {
      EXPECT_GT(std::min(nosesNamed(g, r)[0].a.x(), nosesNamed(g, r)[0].b.x()), 0.0) << r;
    }
  }
}

TEST(TableGeometry, MouthsAndJawAnglesMatchTheSpec) {
  for (const std::string& name : kTables) {
    const TableSpec s = spec(name);
    const TableGeometry g = buildTableGeometry(s);
    for (const std::string& pocket : kPockets) {
      SCOPED_TRACE(name + " " + pocket);
      const bool corner = pocket.ends_with("corner");
      const PocketSpec& ps = corner ? s.corner : s.side;
      const auto facings = facingsOf(g, pocket);
      ASSERT_EQ(facings.size(), 2u);
      EXPECT_NEAR((facings[0].point - facings[1].point).norm(), ps.mouth, 1e-12);
      for (const Facing& f : facings) {
        EXPECT_NEAR(angleDeg(f.rail_other_end - f.point, f.far - f.point), ps.jaw_angle_deg, 1e-9);
      }
      // The facings converge going in, and end at the back of the cushion.
      EXPECT_LT((facings[0].far - facings[1].far).norm(), ps.mouth);
      const Vec2 ref = pocketReference(s, pocket);
      for (const Facing& f : facings) {
        const Vec2 rail_dir = (f.point - f.rail_other_end).normalized();
        const Vec2 outward = Vec2(-rail_dir.y(), rail_dir.x()).dot(f.point) > 0
                                 ? Vec2(-rail_dir.y(), rail_dir.x())
                                 : Vec2(rail_dir.y(), -rail_dir.x());
        EXPECT_NEAR((f.far - f.point).dot(outward), s.cushion_width, 1e-12);
        EXPECT_LT((f.point - ref).norm(), ps.mouth);  // the jaw point is near its pocket
      }
      if (corner) {
        EXPECT_NEAR((facings[0].point - ref).norm(), ps.mouth / std::sqrt(2.0), 1e-12);
      } else {
        EXPECT_NEAR(std::abs(facings[0].point.x()), ps.mouth / 2.0, 1e-12);
      }
    }
  }
}

TEST(TableGeometry, NormalsPointWhereABallMayBe) {
  const TableGeometry g = buildTableGeometry(spec("wpa-9ft"));
  for (const NoseSegment& n : g.noses) {
    SCOPED_TRACE(n.name);
    EXPECT_NEAR(n.normal.norm(), 1.0, 1e-12);
    EXPECT_NEAR(n.normal.dot(n.b - n.a), 0.0, 1e-12);
    const Vec2 left = Vec2(-(n.b - n.a).y(), (n.b - n.a).x()).normalized();
    EXPECT_NEAR((n.normal - left).norm(), 0.0, 1e-12);  // the documented a → b convention
  }
  for (const std::string& r : kRails) {
    const NoseSegment n = nosesNamed(g, r)[0];
    EXPECT_GT(n.normal.dot(-(n.a + n.b) / 2.0), 0.0) << r;  // toward the table centre
  }
  for (const std::string& p : kPockets) {
    const auto f = nosesNamed(g, "jaw_" + p);
    ASSERT_EQ(f.size(), 2u);
    const Vec2 m0 = (f[0].a + f[0].b) / 2.0, m1 = (f[1].a + f[1].b) / 2.0;
    EXPECT_GT(f[0].normal.dot(m1 - m0), 0.0) << p;  // into the opening, toward the other facing
    EXPECT_GT(f[1].normal.dot(m0 - m1), 0.0) << p;
  }
}

TEST(TableGeometry, HolesAreWhereTheSpecPutsThem) {
  for (const std::string& name : kTables) {
    const TableSpec s = spec(name);
    const TableGeometry g = buildTableGeometry(s);
    ASSERT_EQ(g.holes.size(), 6u);
    for (const std::string& pocket : kPockets) {
      SCOPED_TRACE(name + " " + pocket);
      const bool corner = pocket.ends_with("corner");
      const PocketSpec& ps = corner ? s.corner : s.side;
      const PocketHole& h = hole(g, pocket);
      const Vec2 ref = pocketReference(s, pocket);
      // Corners: the pocket's axis of symmetry (45°), away from the table; sides: straight out.
      const Vec2 away =
          corner ? Vec2(ref.x() > 0 ? 1.0 : -1.0, ref.y() > 0 ? 1.0 : -1.0) / std::sqrt(2.0)
                 : Vec2(0.0, ref.y() > 0 ? 1.0 : -1.0);
      EXPECT_NEAR((h.centre - (ref + ps.hole_offset * away)).norm(), 0.0, 1e-12);
      EXPECT_DOUBLE_EQ(h.radius, ps.hole_radius);
      for (const Facing& f : facingsOf(g, pocket)) {
        EXPECT_GT((f.point - h.centre).norm(),
                  h.radius + 0.01);  // the hole stays clear of the jaw points
      }
      // How far past the mouth line a ball centre travels (straight in) before it is over the hole.
      const auto facings = facingsOf(g, pocket);
      const Vec2 mouth_mid = (facings[0].point + facings[1].point) / 2.0;
      const double behind = (h.centre - h.radius * away - mouth_mid).dot(away);
      if (corner) {
        EXPECT_GT(behind, 0.025);
        EXPECT_LT(behind, 0.035);
      } else {
        EXPECT_GT(behind, 0.0);
        EXPECT_LT(behind, 0.02);
      }
    }
  }
}

// ---- mesh ------------------------------------------------------------------------------------

Vec3 triNormal(const MeshPart& p, const std::array<std::uint32_t, 3>& t) {
  return (p.vertices[t[1]] - p.vertices[t[0]]).cross(p.vertices[t[2]] - p.vertices[t[0]]);
}

/// Closest distance from point p to triangle abc.
double pointTriangleDistance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a).normalized();
  const Vec3 q = p - n * (p - a).dot(n);
  const auto inside = [&](const Vec3& u, const Vec3& v) {
    return (v - u).cross(q - u).dot(n) >= 0.0;
  };
  if (inside(a, b) && inside(b, c) && inside(c, a)) return (p - q).norm();
  const auto seg = [&](const Vec3& u, const Vec3& v) {
    const double t = std::clamp((p - u).dot(v - u) / (v - u).squaredNorm(), 0.0, 1.0);
    return (p - (u + t * (v - u))).norm();
  };
  return std::min({seg(a, b), seg(b, c), seg(c, a)});
}

TEST(TableMesh, HasEveryPartWithSaneTriangles) {
  const TableSpec s = spec("wpa-9ft");
  const TableGeometry g = buildTableGeometry(s);
  std::vector<std::string> expected{"slate", "trough"};
  for (const std::string& r : kRails)
    expected.insert(expected.end(), {"cushion_" + r, "rail_" + r});
  for (const std::string& p : kPockets)
    expected.insert(expected.end(), {"jaw_" + p, "pocket_" + p});
  std::size_t total = 0;
  for (const std::string& name : expected) {
    const MeshPart* p = part(g, name);
    ASSERT_NE(p, nullptr) << name;
    EXPECT_FALSE(p->triangles.empty()) << name;
    for (const auto& t : p->triangles) {
      for (std::uint32_t i : t) ASSERT_LT(i, p->vertices.size()) << name;
      EXPECT_GT(triNormal(*p, t).norm(), 1e-14) << name;
    }
    total += p->triangles.size();
  }
  EXPECT_EQ(g.parts.size(), expected.size());
  EXPECT_LT(total, 5000u);
  EXPECT_LT(g.trough_z, -s.slate_thickness);
}

TEST(TableMesh, SlateFacesUpAndLeavesTheHolesOpen) {
  const TableGeometry g = buildTableGeometry(spec("wpa-9ft"));
  const MeshPart& slate = *part(g, "slate");
  double area = 0.0;
  for (const auto& t : slate.triangles) {
    const Vec3 n = triNormal(slate, t);
    EXPECT_GT(n.z(), 0.0);
    area += n.z() / 2.0;
    const Vec3 c = (slate.vertices[t[0]] + slate.vertices[t[1]] + slate.vertices[t[2]]) / 3.0;
    for (const PocketHole& h : g.holes) EXPECT_GT((c.head<2>() - h.centre).norm(), h.radius * 0.99);
  }
  for (const Vec3& v : slate.vertices) EXPECT_EQ(v.z(), 0.0);
  // Outer rectangle minus the six (polygonal) holes.
  const TableSpec s = spec("wpa-9ft");
  const double border = s.cushion_width + s.rail_width;
  double expected = (s.length + 2 * border) * (s.width + 2 * border);
  const double polygon = 0.5 * 48 * std::sin(2.0 * std::numbers::pi / 48);
  for (const PocketHole& h : g.holes) expected -= polygon * h.radius * h.radius;
  EXPECT_NEAR(area, expected, 1e-9);
}

TEST(TableMesh, PocketLinersFaceTheirAxis) {
  const TableGeometry g = buildTableGeometry(spec("wpa-9ft"));
  for (const std::string& name : kPockets) {
    const MeshPart& p = *part(g, "pocket_" + name);
    const PocketHole& h = hole(g, name);
    EXPECT_GE(p.triangles.size(), 64u);
    for (const auto& t : p.triangles) {
      const Vec3 c = (p.vertices[t[0]] + p.vertices[t[1]] + p.vertices[t[2]]) / 3.0;
      EXPECT_GT(triNormal(p, t).head<2>().dot(h.centre - c.head<2>()), 0.0) << name;
    }
  }
}

/// Signed volume of a part (positive when a closed part's triangles face outward).
double signedVolume(const MeshPart& p) {
  double v = 0.0;
  for (const auto& t : p.triangles)
    v += p.vertices[t[0]].dot(p.vertices[t[1]].cross(p.vertices[t[2]])) / 6.0;
  return v;
}

void expectClosedCushions(const TableGeometry& g) {
  // Together the cushions and jaws close up (every edge shared by two triangles in opposite order).
  std::map<std::pair<std::array<double, 3>, std::array<double, 3>>, int> edges;
  double volume = 0.0;
  for (const MeshPart& p : g.parts) {
    if (!p.name.starts_with("cushion_") && !p.name.starts_with("jaw_")) continue;
    volume += signedVolume(p);
    for (const auto& t : p.triangles) {
      for (int k = 0; k < 3; ++k) {
        const Vec3& a = p.vertices[t[static_cast<std::size_t>(k)]];
        const Vec3& b = p.vertices[t[static_cast<std::size_t>((k + 1) % 3)]];
        ++edges[{{a.x(), a.y(), a.z()}, {b.x(), b.y(), b.z()}}];
        --edges[{{b.x(), b.y(), b.z()}, {a.x(), a.y(), a.z()}}];
      }
    }
  }
  for (const auto& [edge, balance] : edges) EXPECT_EQ(balance, 0);
  EXPECT_GT(volume, 0.0);
  for (const MeshPart& p : g.parts) {
    if (p.name.starts_with("rail_")) {
      EXPECT_GT(signedVolume(p), 0.0) << p.name;
    }
  }
}

TEST(TableMesh, CushionsAndJawsFormClosedSolidsFacingOut) {
  // With pockets the cushions close into the jaws; without them into each other at the corners.
  for (const char* name : {"wpa-9ft", "carom-match"}) {
    SCOPED_TRACE(name);
    expectClosedCushions(buildTableGeometry(spec(name)));
  }
}

TEST(TableMesh, ABallTouchingANoseTouchesNothingElse) {
  for (const std::string& name : kAllTables) {
    const TableSpec s = spec(name);
    const TableGeometry g = buildTableGeometry(s);
    const double r = s.params.ball_radius;
    const double h = s.params.cushion_height;
    const double reach = std::sqrt(r * r - (h - r) * (h - r));  // centre to nose line, horizontally
    for (const NoseSegment& n : g.noses) {
      for (double t : {0.25, 0.5, 0.75}) {
        const Vec2 touch = n.a + t * (n.b - n.a);
        const Vec3 centre(touch.x() + reach * n.normal.x(), touch.y() + reach * n.normal.y(), r);
        double nearest = 1.0;
        for (const MeshPart& p : g.parts) {
          if (!p.name.starts_with("cushion_") && !p.name.starts_with("jaw_")) continue;
          for (const auto& tri : p.triangles) {
            nearest =
                std::min(nearest, pointTriangleDistance(centre, p.vertices[tri[0]],
                                                        p.vertices[tri[1]], p.vertices[tri[2]]));
          }
        }
        EXPECT_NEAR(nearest, r, 1e-9) << name << " " << n.name << " at " << t;
      }
    }
  }
}

// ---- OBJ and assimp ----------------------------------------------------------------------------

TEST(TableObj, CommittedMeshesAreReproducible) {
  for (const std::string& name : kAllTables) {
    const std::filesystem::path path =
        std::filesystem::path(POOL_SOURCE_DIR) / "assets" / "tables" / (name + ".obj");
    std::ifstream in(path, std::ios::binary);
    ASSERT_TRUE(in) << path;
    std::stringstream committed;
    committed << in.rdbuf();
    EXPECT_TRUE(committed.str() == toObj(buildTableGeometry(spec(name))))
        << path << " is stale: regenerate it with `pool-tablegen " << name << " -o "
        << path.string() << "`";
  }
}

TEST(TableObj, OutputIsDeterministicAndLabelled) {
  const TableGeometry g = buildTableGeometry(spec("wpa-8ft"));
  const std::string obj = toObj(g);
  EXPECT_EQ(obj, toObj(buildTableGeometry(spec("wpa-8ft"))));
  EXPECT_TRUE(obj.starts_with("# table wpa-8ft")) << obj.substr(0, 80);
  EXPECT_EQ(obj.find("-0.000000000"), std::string::npos);
  EXPECT_NE(obj.find("\no nose_jaw_left_side\n"), std::string::npos);
  EXPECT_NE(obj.find("\no hole_right_side\n"), std::string::npos);
  EXPECT_NE(obj.find("\no slate\n"), std::string::npos);
}

TEST(TableObj, AssimpRoundTripMatchesTheBuiltGeometry) {
  for (const std::string& name : kAllTables) {
    SCOPED_TRACE(name);
    const TableSpec s = spec(name);
    const TableGeometry built = buildTableGeometry(s);
    const auto loaded = loadTableGeometry(s);
    ASSERT_TRUE(loaded) << loaded.error();
    const TableGeometry& g = *loaded;
    EXPECT_EQ(g.length, s.length);
    EXPECT_EQ(g.width, s.width);
    EXPECT_NEAR(g.nose_height, s.params.cushion_height, 1e-6);
    EXPECT_EQ(g.trough_z, built.trough_z);
    ASSERT_EQ(g.noses.size(), built.noses.size());
    for (std::size_t i = 0; i < g.noses.size(); ++i) {
      EXPECT_EQ(g.noses[i].name, built.noses[i].name);
      EXPECT_LT((g.noses[i].a - built.noses[i].a).norm(), 1e-6) << built.noses[i].name;
      EXPECT_LT((g.noses[i].b - built.noses[i].b).norm(), 1e-6) << built.noses[i].name;
      EXPECT_LT((g.noses[i].normal - built.noses[i].normal).norm(), 1e-6) << built.noses[i].name;
    }
    ASSERT_EQ(g.holes.size(), built.holes.size());
    for (std::size_t i = 0; i < g.holes.size(); ++i) {
      EXPECT_EQ(g.holes[i].name, built.holes[i].name);
      EXPECT_LT((g.holes[i].centre - built.holes[i].centre).norm(), 1e-6) << built.holes[i].name;
      EXPECT_NEAR(g.holes[i].radius, built.holes[i].radius, 1e-6) << built.holes[i].name;
    }
    ASSERT_EQ(g.parts.size(), built.parts.size());
    for (std::size_t i = 0; i < g.parts.size(); ++i) {
      const MeshPart& a = g.parts[i];
      const MeshPart& b = built.parts[i];
      EXPECT_EQ(a.name, b.name);
      ASSERT_EQ(a.triangles.size(), b.triangles.size()) << b.name;
      double worst = 0.0;
      for (std::size_t t = 0; t < a.triangles.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
          const auto kk = static_cast<std::size_t>(k);
          worst = std::max(
              worst, (a.vertices[a.triangles[t][kk]] - b.vertices[b.triangles[t][kk]]).norm());
        }
      }
      EXPECT_LT(worst, 1e-6) << b.name;
    }
  }
}

TEST(TableObj, LoadFailuresAreReasons) {
  TableSpec s = spec("wpa-9ft");
  s.collision_mesh.clear();
  const auto unset = loadTableGeometry(s);
  ASSERT_FALSE(unset);
  EXPECT_EQ(unset.error(), "collision_mesh: not set in the spec");
  s.collision_mesh = "/nonexistent/table.obj";
  const auto missing = loadTableGeometry(s);
  ASSERT_FALSE(missing);
  EXPECT_TRUE(missing.error().starts_with("collision_mesh: /nonexistent/table.obj"))
      << missing.error();
  EXPECT_EQ(missing.error().find('\n'), std::string::npos) << missing.error();
}

}  // namespace
}  // namespace pool::table
