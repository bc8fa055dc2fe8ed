#include "mujoco_runner.hpp"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace unfurl::peer {

namespace {

struct Latch {
  int joint = 0, qpos = 0, dof = 0;
  double position = 0, stiffness = 0, damping = 0, side = 0;
  bool engaged = false;
  double engaged_at = NAN;
};

// unfurl's joint limits (limit:JOINT), in place of MuJoCo's own.
struct Limit {
  int qpos = 0, dof = 0;
  double lower = 0, upper = 0, stiffness = 0, damping = 0;
  double penetration(const mjData* d) const {
    const double q = d->qpos[qpos];
    return q > upper ? q - upper : q < lower ? q - lower : 0.0;
  }
};

// The run in progress: mjcb_passive takes no user data.
std::vector<Latch> latches;
std::vector<Limit> limits;

// Engaged latches and the limits as joint torques, at every stage of the
// step; a limit pushes and never pulls.
void passive_torques(const mjModel*, mjData* d) {
  for (const Latch& l : latches)
    if (l.engaged)
      d->qfrc_passive[l.dof] += -l.stiffness * (d->qpos[l.qpos] - l.position) - l.damping * d->qvel[l.dof];
  for (const Limit& l : limits) {
    const double x = l.penetration(d);
    if (x == 0) continue;
    const double tau = -l.stiffness * x - l.damping * d->qvel[l.dof];
    if (tau * x < 0) d->qfrc_passive[l.dof] += tau;
  }
}

// Reads them and turns MuJoCo's own limits on their joints off.
std::vector<Limit> read_limits(mjModel* m) {
  std::vector<Limit> out;
  for (int i = 0; i < m->nnumeric; ++i) {
    const std::string name = mj_id2name(m, mjOBJ_NUMERIC, i);
    if (name.rfind("limit:", 0) != 0 || m->numeric_size[i] != 4) continue;
    const int joint = mj_name2id(m, mjOBJ_JOINT, name.substr(6).c_str());
    if (joint < 0) continue;
    m->jnt_limited[joint] = 0;
    const mjtNum* data = m->numeric_data + m->numeric_adr[i];
    out.push_back({m->jnt_qposadr[joint], m->jnt_dofadr[joint], data[0], data[1], data[2], data[3]});
  }
  return out;
}

std::vector<Latch> read_latches(const mjModel* m) {
  std::vector<Latch> out;
  for (int i = 0; i < m->nnumeric; ++i) {
    const std::string name = mj_id2name(m, mjOBJ_NUMERIC, i);
    if (name.rfind("latch:", 0) != 0 || m->numeric_size[i] != 4) continue;
    Latch l;
    l.joint = mj_name2id(m, mjOBJ_JOINT, name.substr(6).c_str());
    if (l.joint < 0) continue;
    l.qpos = m->jnt_qposadr[l.joint];
    l.dof = m->jnt_dofadr[l.joint];
    const mjtNum* data = m->numeric_data + m->numeric_adr[i];
    l.position = data[0], l.stiffness = data[1], l.damping = data[2], l.side = data[3];
    l.engaged = l.side == 0;
    if (l.engaged) l.engaged_at = 0;
    out.push_back(l);
  }
  return out;
}

double latch_and_limit_energy(const mjData* d) {
  double e = 0;
  for (const Latch& l : latches)
    if (l.engaged) e += 0.5 * l.stiffness * std::pow(d->qpos[l.qpos] - l.position, 2);
  for (const Limit& l : limits) e += 0.5 * l.stiffness * std::pow(l.penetration(d), 2);
  return e;
}

int warnings(const mjData* d) {
  int n = 0;
  for (int i = 0; i < mjNWARNING; ++i) n += d->warning[i].number;
  return n;
}

}  // namespace

MujocoRun run_mujoco(const std::string& xml_path, double t_end, double dt, double sample) {
  char error[1000] = "";
  mjModel* m = mj_loadXML(xml_path.c_str(), nullptr, error, sizeof error);
  if (!m || error[0]) {
    if (m) mj_deleteModel(m);
    throw std::runtime_error(xml_path + ": " + (error[0] ? error : "cannot load"));
  }
  m->opt.timestep = dt;
  m->opt.integrator = mjINT_RK4;
  mjData* d = mj_makeData(m);
  if (m->nkey > 0) mj_resetDataKeyframe(m, d, 0);
  latches = read_latches(m);
  limits = read_limits(m);
  mjcb_passive = passive_torques;

  MujocoRun run;
  // Every entry of qpos, named as unfurl names its q: a hinge or slide by
  // its joint, a free joint's "NAME.x" ... "NAME.qz", a ball's "NAME.qw" ...
  static const char* const free_entries[] = {"x", "y", "z", "qw", "qx", "qy", "qz"};
  static const char* const ball_entries[] = {"qw", "qx", "qy", "qz"};
  std::vector<int> entry_qpos;
  for (int j = 0; j < m->njnt; ++j) {
    const std::string name = mj_id2name(m, mjOBJ_JOINT, j);
    const int type = m->jnt_type[j];
    const int n = type == mjJNT_FREE ? 7 : type == mjJNT_BALL ? 4 : 1;
    for (int k = 0; k < n; ++k) {
      run.joints.push_back(n == 1 ? name
                                  : name + "." + (type == mjJNT_FREE ? free_entries[k] : ball_entries[k]));
      entry_qpos.push_back(m->jnt_qposadr[j] + k);
    }
  }
  auto record = [&](double t) {
    mj_forward(m, d);
    run.t.push_back(t);
    std::vector<double> q;
    for (int a : entry_qpos) q.push_back(d->qpos[a]);
    run.q.push_back(std::move(q));
    run.energy.push_back(d->energy[0] + d->energy[1] + latch_and_limit_energy(d));
  };
  const long steps = std::lround(t_end / dt), per_sample = std::max(1L, std::lround(sample / dt));
  std::vector<mjtNum> qpos(m->nq), qvel(m->nv);
  double stepping = 0;  // seconds in the stepping loop, recording excluded
  record(0);
  for (long k = 1; k <= steps; ++k) {
    const auto start = std::chrono::steady_clock::now();
    // One step of dt, cut at every latch crossing inside it: step to the
    // earliest crossing (on the straight line between the ends of the trial
    // step), engage, go on with the rest. Each cut engages a latch.
    double remaining = dt;
    while (remaining > 0) {
      std::copy(d->qpos, d->qpos + m->nq, qpos.begin());
      std::copy(d->qvel, d->qvel + m->nv, qvel.begin());
      const double t0 = d->time;
      std::vector<double> before(latches.size());
      for (std::size_t i = 0; i < latches.size(); ++i)
        before[i] = latches[i].side * (d->qpos[latches[i].qpos] - latches[i].position);
      m->opt.timestep = remaining;
      mj_step(m, d);
      ++run.steps;
      double first = 2.0;
      std::vector<double> crossing(latches.size(), 2.0);
      for (std::size_t i = 0; i < latches.size(); ++i) {
        const Latch& l = latches[i];
        const double after = l.side * (d->qpos[l.qpos] - l.position);
        if (l.engaged || after > 0) continue;
        crossing[i] = before[i] <= 0 ? 0.0 : before[i] / (before[i] - after);
        first = std::min(first, crossing[i]);
      }
      if (first > 1.0) break;
      std::copy(qpos.begin(), qpos.end(), d->qpos);
      std::copy(qvel.begin(), qvel.end(), d->qvel);
      d->time = t0;
      const double h = first * remaining;
      if (h > 0) {
        m->opt.timestep = h;
        mj_step(m, d);
        ++run.steps;
      }
      for (std::size_t i = 0; i < latches.size(); ++i)
        if (crossing[i] <= first + 1e-9) {
          latches[i].engaged = true;
          latches[i].engaged_at = t0 + h;
        }
      remaining -= h;
    }
    m->opt.timestep = dt;
    stepping += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (k % per_sample == 0) record(k * dt);
  }
  run.wall_s = stepping;
  for (const Latch& l : latches)
    if (l.engaged) run.latches.emplace_back(l.engaged_at, mj_id2name(m, mjOBJ_JOINT, l.joint));
  std::sort(run.latches.begin(), run.latches.end());
  run.warnings = warnings(d);
  mjcb_passive = nullptr;
  mj_deleteData(d);
  mj_deleteModel(m);
  return run;
}

}  // namespace unfurl::peer
