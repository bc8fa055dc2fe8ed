#include "unfurl/studies/clearance.hpp"

#include <fcl/fcl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <unordered_set>

#include "unfurl/sim/kinematics.hpp"
#include "unfurl/studies/clearance_broad_phase.hpp"

namespace unfurl::studies {

namespace {

using Kind = sim::CollisionShape::Kind;
constexpr double kInf = std::numeric_limits<double>::infinity();

struct FclSolid {
  std::shared_ptr<fcl::CollisionGeometryd> geometry;
  bool mesh = false;
  fcl::Transform3d local = fcl::Transform3d::Identity();  // solid -> body
};

// A body as clearance sees it: a model body (or the base) with the loop
// images that are its other halves.
struct PhysicalBody {
  std::string name;
  int body = sim::kBase;  // the model body its solids are on
  std::vector<FclSolid> solids;
  double reach = 0;
  BodyBox bound;  // body frame
};

std::shared_ptr<fcl::CollisionGeometryd> fcl_geometry(const Solid& s) {
  switch (s.kind) {
    case Kind::box: return std::make_shared<fcl::Boxd>(s.size);
    case Kind::sphere: return std::make_shared<fcl::Sphered>(s.radius);
    case Kind::cylinder: return std::make_shared<fcl::Cylinderd>(s.radius, s.length);
    case Kind::mesh: break;
  }
  std::vector<fcl::Vector3d> vertices(s.mesh.vertices.begin(), s.mesh.vertices.end());
  std::vector<fcl::Triangle> faces;
  for (const auto& f : s.mesh.faces) faces.emplace_back(f[0], f[1], f[2]);
  auto bvh = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
  bvh->beginModel(static_cast<int>(faces.size()), static_cast<int>(vertices.size()));
  bvh->addSubModel(vertices, faces);
  bvh->endModel();
  return bvh;
}

fcl::Transform3d world(const sim::Pose& pose) {
  fcl::Transform3d T = fcl::Transform3d::Identity();
  T.linear() = pose.rotation.transpose();
  T.translation() = pose.position;
  return T;
}

// How far any point of body b within `reach_b` of its origin can have moved
// relative to body a from poses (a0, b0) to (a1, b1): the chord of b's
// origin in a's frame plus reach_b times the angle b turned relative to a;
// or the same of a in b's frame, whichever bounds it tighter. Their
// distance changes by no more than that.
double relative_displacement_bound(const sim::Pose& a0, const sim::Pose& b0, const sim::Pose& a1, const sim::Pose& b1,
                                   double reach_a, double reach_b) {
  // G_0^i maps the base frame to body i's; b's origin in a's frame is
  // G_a (r_b - r_a), and b's frame relative to a's is G_b G_a^T.
  const auto one_way = [](const sim::Pose& from0, const sim::Pose& to0, const sim::Pose& from1,
                          const sim::Pose& to1, double reach) {
    const sim::Vec3 p0 = from0.rotation * (to0.position - from0.position);
    const sim::Vec3 p1 = from1.rotation * (to1.position - from1.position);
    const sim::Mat3 turn = (to1.rotation * from1.rotation.transpose()) * (to0.rotation * from0.rotation.transpose()).transpose();
    return (p1 - p0).norm() + reach * Eigen::AngleAxisd(turn).angle();
  };
  return std::min(one_way(a0, b0, a1, b1, reach_b), one_way(b0, a0, b1, a1, reach_a));
}

class ClearanceCheck {
 public:
  ClearanceCheck(const sim::Scene& scene, const BodySolids& solids, const sim::Trajectory& trajectory)
      : scene_(scene), trajectory_(trajectory) {
    gather_bodies(solids);
    gather_pairs();
    sample_poses();
  }

  // The pairs that come within a margin of each other, the margin doubled
  // from a tenth of the largest body's reach until the closest pair
  // measured lies within it: every pair left out is then farther apart
  // than the margin, and than the closest, throughout.
  sim::Clearance run(const std::atomic<bool>* cancel) {
    std::unordered_set<std::uint64_t> measured;
    long left = pairs_;
    double margin = 0.1 * length_;
    for (;;) {
      const NearPairs near(
          boxes_, poses_.size(), [&](std::size_t k, int s) -> const sim::Pose& { return pose(poses_[k], s); }, margin);
      for (const auto& [a, b] : near.pairs()) {
        if (joined_.count(key(a, b)) || !measured.insert(key(a, b)).second) continue;
        if (cancel && cancel->load(std::memory_order_relaxed)) return out_;
        scan(a, b);
        --left;
      }
      if (left == 0 || closest_ <= margin) break;
      margin = margin > 0 ? 2 * margin : kInf;
    }
    out_.listed_within = left == 0 ? kInf : margin;
    out_.pairs_beyond = left;
    // Among pairs at the same distance (touching), the earliest first, then
    // the scene's order: the closest pair is the first contact.
    std::stable_sort(out_.pairs.begin(), out_.pairs.end(), [](const auto& x, const auto& y) {
      return x.distance < y.distance || (x.distance == y.distance && x.t < y.t);
    });
    std::stable_sort(out_.contacts.begin(), out_.contacts.end(),
                     [](const auto& x, const auto& y) { return x.t_begin < y.t_begin; });
    out_.samples = static_cast<int>(trajectory_.samples.size());
    return out_;
  }

 private:
  // Every body but a loop's image, which is its split body's other half,
  // and a solid-less body fixed to its parent.
  void gather_bodies(const BodySolids& solids) {
    const sim::Model& m = scene_.model;
    slot_of_.assign(m.size(), -1);
    std::vector<int> image_of(m.size(), -1);
    for (const sim::Loop& loop : scene_.loops) image_of[loop.image] = loop.body;
    const auto add = [&](int body, const std::string& name, const std::vector<Solid>& list) {
      PhysicalBody p;
      p.name = name;
      p.body = body;
      for (const Solid& s : list) {
        FclSolid f{fcl_geometry(s), s.kind == Kind::mesh, fcl::Transform3d::Identity()};
        f.local.linear() = s.rotation;
        f.local.translation() = s.offset;
        p.solids.push_back(std::move(f));
        p.reach = std::max(p.reach, s.reach());
      }
      p.bound = enclosing_box(list);
      if (p.solids.empty()) out_.without_solid.push_back(name);
      bodies_.push_back(std::move(p));
      return static_cast<int>(bodies_.size()) - 1;
    };
    if (!m.free_floating()) base_slot_ = add(sim::kBase, m.base_name, solids.base);
    // A body fixed to its parent without a solid of its own (a loop's pin
    // on a flexible panel) is part of the parent, and so is its image.
    std::vector<bool> part(m.size(), false);
    for (int i = 0; i < m.size(); ++i) {
      part[i] = image_of[i] < 0 && m.joints[i].type == sim::JointType::fixed && solids.bodies[i].empty() &&
                m.parent[i] >= 0;
      if (image_of[i] < 0 && !part[i]) slot_of_[i] = add(i, m.bodies[i].name, solids.bodies[i]);
    }
    for (bool changed = true; changed;) {
      changed = false;
      for (int i = 0; i < m.size(); ++i) {
        const int from = part[i] ? m.parent[i] : image_of[i];
        if (slot_of_[i] >= 0 || from < 0 || slot_of_[from] < 0) continue;
        slot_of_[i] = slot_of_[from];
        changed = true;
      }
    }
  }

  int slot(int body) const { return body == sim::kBase ? base_slot_ : slot_of_[body]; }

  static std::uint64_t key(int a, int b) {
    const auto [low, high] = std::minmax(a, b);
    return static_cast<std::uint64_t>(low) << 32 | static_cast<std::uint64_t>(high);
  }

  // The pairs a joint, a loop or a bushing holds together, and how many of
  // bodies with solids are left (the pairs to check; the broad phase lists
  // the near ones, so that none is listed N^2 times).
  void gather_pairs() {
    const auto join = [&](int a, int b) {
      const int sa = slot(a), sb = slot(b);
      if (sa >= 0 && sb >= 0 && sa != sb) joined_.insert(key(sa, sb));
    };
    for (int i = 0; i < scene_.model.size(); ++i) join(i, scene_.model.parent[i]);
    for (const auto& element : scene_.elements)
      for (const sim::ElementLink& link : element->links())
        if (link.style == sim::ElementLink::Style::bushing) join(link.body_a, link.body_b);
    const auto with_solids = [&](int x) { return !bodies_[x].solids.empty(); };
    long n = 0;
    for (int x = 0; x < static_cast<int>(bodies_.size()); ++x) n += with_solids(x);
    pairs_ = n * (n - 1) / 2;
    for (const std::uint64_t k : joined_)
      if (with_solids(static_cast<int>(k >> 32)) && with_solids(static_cast<int>(k & 0xffffffffu))) --pairs_;
  }

  void poses_at(const double* q, std::vector<sim::Pose>& out) const { sim::body_poses(scene_.model, q, out); }

  const sim::Pose& pose(const std::vector<sim::Pose>& poses, int slot) const {
    static const sim::Pose kBasePose;
    return bodies_[slot].body == sim::kBase ? kBasePose : poses[bodies_[slot].body];
  }

  void sample_poses() {
    const auto& samples = trajectory_.samples;
    poses_.resize(samples.size());
    for (std::size_t k = 0; k < samples.size(); ++k)
      poses_at(samples[k].y.data() + trajectory_.layout.q(), poses_[k]);
    for (const PhysicalBody& b : bodies_) length_ = std::max(length_, b.reach);
    resolution_ = 1e-4 * length_;
    for (const PhysicalBody& b : bodies_) boxes_.push_back(b.bound);
  }

  // The distance between two bodies' solids at the poses (0: touching or
  // interpenetrating, within a billionth of the bodies' size).
  // With `in_contact` (as they were at the sample before), whether they
  // still are is asked first: a collision query stops at the first crossing.
  double distance(int a, int b, const std::vector<sim::Pose>& poses, bool in_contact = false) {
    ++out_.distance_queries;
    const fcl::Transform3d Ta = world(pose(poses, a)), Tb = world(pose(poses, b));
    if (in_contact)
      for (const FclSolid& x : bodies_[a].solids)
        for (const FclSolid& y : bodies_[b].solids)
          if (collide(x, Ta * x.local, y, Tb * y.local)) return 0;
    double d = kInf;
    for (const FclSolid& x : bodies_[a].solids)
      for (const FclSolid& y : bodies_[b].solids) d = std::min(d, solid_distance(x, Ta * x.local, y, Tb * y.local));
    return d;
  }

  double solid_distance(const FclSolid& x, const fcl::Transform3d& Tx, const FclSolid& y,
                        const fcl::Transform3d& Ty) const {
    // FCL measures a mesh against a primitive with the mesh first. Its
    // distance is unsigned (negative or 0 once the solids overlap): the
    // signed one's penetration search (EPA) aborts on an assertion in
    // Debian's FCL 0.7 for two spheres a little inside each other. A mesh
    // and a primitive that overlap get no defined distance: the collision
    // query goes first.
    if (!x.mesh && y.mesh) return solid_distance(y, Ty, x, Tx);
    if (x.mesh && !y.mesh && collide(x, Tx, y, Ty)) return 0;
    fcl::DistanceRequestd request;
    // GJK's convergence: FCL's default is an absolute 1e-6 (a micrometre
    // or a kilometre alike); ours, the contact distance, is the scene's.
    request.distance_tolerance = 1e-9 * length_;
    fcl::DistanceResultd result;
    const double d = fcl::distance(x.geometry.get(), Tx, y.geometry.get(), Ty, request, result);
    return d > 1e-9 * length_ ? d : 0;
  }

  static bool collide(const FclSolid& x, const fcl::Transform3d& Tx, const FclSolid& y, const fcl::Transform3d& Ty) {
    if (!x.mesh && y.mesh) return collide(y, Ty, x, Tx);
    fcl::CollisionRequestd request;
    fcl::CollisionResultd result;
    return fcl::collide(x.geometry.get(), Tx, y.geometry.get(), Ty, request, result) > 0;
  }

  double distance_at(int a, int b, double t) {
    trajectory_.coordinates_at(t, q_);
    poses_at(q_.data(), scratch_);
    return distance(a, b, scratch_);
  }

  double motion_between(int a, int b, double ta, double tb) {
    trajectory_.coordinates_at(ta, q_);
    poses_at(q_.data(), scratch_);
    const sim::Pose a0 = pose(scratch_, a), b0 = pose(scratch_, b);
    trajectory_.coordinates_at(tb, q_);
    poses_at(q_.data(), scratch_);
    return relative_displacement_bound(a0, b0, pose(scratch_, a), pose(scratch_, b), bodies_[a].reach,
                                       bodies_[b].reach);
  }

  struct Closest {
    double distance = kInf, t = 0;
    std::size_t k = 0;  // the sample it was measured at (or near)
  };

  // Every sample where the pair may come closer than it has been (or touch),
  // the paths between the samples measured, and the closest refined.
  void scan(int a, int b) {
    const auto& samples = trajectory_.samples;
    Closest best;
    double last_d = distance(a, b, poses_[0]), moved = 0;
    std::size_t last_k = 0;
    consider(a, b, 0, last_d, false, best);
    for (std::size_t k = 1; k < samples.size(); ++k) {
      const double step = step_bound(a, b, k);
      moved += step;
      if (last_d - moved > std::max(best.distance - resolution_, 0.0)) continue;
      const double d = distance(a, b, poses_[k], last_k + 1 == k && last_d <= 0);
      double d_before = last_k + 1 == k ? last_d : last_d - (moved - step);
      if (last_k + 1 != k && d > 0 && d_before + d <= step) d_before = distance(a, b, poses_[k - 1]);
      if (d_before > 0 && d > 0 && d_before + d <= step)
        bisect(a, b, samples[k - 1].t, d_before, samples[k].t, d, 0, best);
      consider(a, b, k, d, last_k + 1 == k && last_d <= 0, best);
      last_d = d;
      last_k = k;
      moved = 0;
    }
    if (best.distance > 0) refine(a, b, best);
    closest_ = std::min(closest_, best.distance);
    out_.pairs.push_back({bodies_[a].name, bodies_[b].name, best.distance, best.t});
  }

  double step_bound(int a, int b, std::size_t k) const {
    return relative_displacement_bound(pose(poses_[k - 1], a), pose(poses_[k - 1], b), pose(poses_[k], a),
                                       pose(poses_[k], b), bodies_[a].reach, bodies_[b].reach);
  }

  void consider(int a, int b, std::size_t k, double d, bool contact_continues, Closest& best) {
    const double t = trajectory_.samples[k].t;
    if (d < best.distance) best = {d, t, k};
    if (d <= 0) note_contact(a, b, t, contact_continues, k == 0);
  }

  // Halves [ta, tb] until the pair's motion cannot close the distances at
  // its ends, down to an eighth of the span.
  void bisect(int a, int b, double ta, double da, double tb, double db, int depth, Closest& best) {
    constexpr int kDepth = 3;
    if (da + db > motion_between(a, b, ta, tb) || depth == kDepth) return;
    const double tm = 0.5 * (ta + tb);
    const double dm = distance_at(a, b, tm);
    if (dm < best.distance) best = {dm, tm, best.k};
    if (dm <= 0) {
      note_contact(a, b, tm, false, false);
      return;
    }
    bisect(a, b, ta, da, tm, dm, depth + 1, best);
    bisect(a, b, tm, dm, tb, db, depth + 1, best);
  }

  void note_contact(int a, int b, double t, bool continues, bool at_start) {
    if (continues)
      for (auto c = out_.contacts.rbegin(); c != out_.contacts.rend(); ++c)
        if (c->body_a == bodies_[a].name && c->body_b == bodies_[b].name) {
          c->t_end = t;
          return;
        }
    out_.contacts.push_back({bodies_[a].name, bodies_[b].name, t, t, at_start});
  }

  // Golden-section search for the closest approach between the samples
  // either side of the closest one.
  void refine(int a, int b, Closest& best) {
    const auto& samples = trajectory_.samples;
    if (samples.size() < 2) return;
    const std::size_t before = best.k == 0 ? 0 : best.k - 1, after = std::min(best.k + 1, samples.size() - 1);
    // Where the pair hardly moves about its closest sample, that sample is
    // the closest approach to within the resolution.
    double moved = 0;
    for (std::size_t k = before + 1; k <= after; ++k) moved += step_bound(a, b, k);
    if (moved <= resolution_) return;
    double lo = samples[before].t, hi = samples[after].t;
    const double tolerance = 1e-4 * (hi - lo);
    const double g = 0.5 * (std::sqrt(5.0) - 1);
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    double f1 = distance_at(a, b, x1), f2 = distance_at(a, b, x2);
    while (hi - lo > tolerance) {
      if (f1 < f2) {
        hi = x2, x2 = x1, f2 = f1;
        x1 = hi - g * (hi - lo);
        f1 = distance_at(a, b, x1);
      } else {
        lo = x1, x1 = x2, f1 = f2;
        x2 = lo + g * (hi - lo);
        f2 = distance_at(a, b, x2);
      }
    }
    if (f1 < best.distance) best = {f1, x1, best.k};
    if (f2 < best.distance) best = {f2, x2, best.k};
    if (best.distance <= 0) note_contact(a, b, best.t, false, false);
  }

  const sim::Scene& scene_;
  const sim::Trajectory& trajectory_;
  std::vector<PhysicalBody> bodies_;
  std::vector<int> slot_of_;
  int base_slot_ = -1;
  std::unordered_set<std::uint64_t> joined_;   // key(a, b) of slots held together
  long pairs_ = 0;                             // pairs of bodies with solids, not held together
  std::vector<std::vector<sim::Pose>> poses_;  // per sample
  std::vector<BodyBox> boxes_;                 // per physical body
  double closest_ = kInf;                      // over the pairs measured
  double length_ = 0;                          // the largest reach
  // How close to a pair's closest approach its reported one is: a
  // ten-thousandth of the largest body.
  double resolution_ = 0;
  std::vector<double> q_;
  std::vector<sim::Pose> scratch_;
  sim::Clearance out_;
};

}  // namespace

sim::Clearance check_clearance(const sim::Scene& scene, const BodySolids& solids, const sim::Trajectory& trajectory,
                               const std::atomic<bool>* cancel) {
  if (solids.bodies.size() != static_cast<std::size_t>(scene.model.size()))
    throw std::invalid_argument("check_clearance: solids for " + std::to_string(solids.bodies.size()) +
                                " bodies, the scene has " + std::to_string(scene.model.size()));
  const auto start = std::chrono::steady_clock::now();
  sim::Clearance out;
  // Already cancelled: not even the bodies' hierarchies and poses (seconds
  // on a large array under a sanitizer).
  if (cancel && cancel->load(std::memory_order_relaxed)) return out;
  if (!trajectory.empty()) out = ClearanceCheck(scene, solids, trajectory).run(cancel);
  out.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace unfurl::studies
