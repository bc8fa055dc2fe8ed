#include "unfurl/sim/flexible/inertia_invariants.hpp"

#include "unfurl/sim/spatial.hpp"

namespace unfurl::sim::flexible {

InertiaInvariants::InertiaInvariants(const std::vector<MassPoint>& points, const Eigen::MatrixXd& shape,
                                     const std::vector<Shortening>& shortening)
    : m_(static_cast<int>(shape.cols())),
      S0_(Vec3::Zero()),
      S1_(Eigen::Matrix3Xd::Zero(3, m_)),
      C0_(Eigen::Matrix3Xd::Zero(3, m_)),
      J0_(Mat3::Zero()),
      S2_(m_ * m_, Vec3::Zero()),
      E_(m_, Eigen::Matrix3Xd::Zero(3, m_)),
      J1_(m_, Mat3::Zero()),
      J2_(m_ * m_, Mat3::Zero()),
      C1_(m_, Eigen::Matrix3Xd::Zero(3, m_)),
      Me_(Eigen::MatrixXd::Zero(m_, m_)) {
  Eigen::MatrixXd local(0, m_);
  for (size_t g = 0; g < points.size(); ++g) {
    const MassPoint& p = points[g];
    local.resize(p.dofs.size(), m_);
    for (size_t a = 0; a < p.dofs.size(); ++a) local.row(a) = shape.row(p.dofs[a]);
    const Eigen::Matrix3Xd Phi = p.N * local, Psi = p.R * local;
    const Mat3 r = skew(p.r);
    mass_ += p.m;
    S0_ += p.m * p.r;
    S1_ += p.m * Phi;
    J0_ += p.m * r.transpose() * r + p.J;
    C0_ += p.m * r * Phi + p.J * Psi;
    Me_ += p.m * Phi.transpose() * Phi + Psi.transpose() * p.J * Psi;
    for (int k = 0; k < m_; ++k) {
      const Mat3 phi_k = skew(Phi.col(k));
      J1_[k] += p.m * (r.transpose() * phi_k + phi_k.transpose() * r);
      C1_[k] += p.m * phi_k * Phi;
      for (int l = 0; l < m_; ++l) J2_[k * m_ + l] += p.m * phi_k.transpose() * skew(Phi.col(l));
    }
    if (shortening.empty()) continue;
    const Vec3 e = shortening[g].axis;
    const Eigen::MatrixXd& G = shortening[g].G;
    const Mat3 e_skew = skew(e);
    for (int k = 0; k < m_; ++k) {
      const Eigen::Matrix3Xd e_Gk = e * G.row(k);  // 3 x m
      E_[k] += p.m * e_Gk;
      C1_[k] -= p.m * r * e_Gk;
      for (int l = 0; l < m_; ++l) {
        S2_[k * m_ + l] += p.m * G(k, l) * e;
        J2_[k * m_ + l] -= 0.5 * p.m * G(k, l) * (r.transpose() * e_skew + e_skew.transpose() * r);
      }
    }
  }
}

Eigen::MatrixXd InertiaInvariants::mass_matrix(const Eigen::VectorXd& eta) const {
  Eigen::MatrixXd M(6 + m_, 6 + m_);
  mass_matrix(eta.data(), M);
  return M;
}

Eigen::MatrixXd InertiaInvariants::mass_matrix_rate(const Eigen::VectorXd& eta, const Eigen::VectorXd& eta_dot) const {
  Eigen::MatrixXd M(6 + m_, 6 + m_);
  mass_matrix_rate(eta.data(), eta_dot.data(), M);
  return M;
}

Eigen::VectorXd InertiaInvariants::kinetic_gradient(const Eigen::VectorXd& eta, const Eigen::VectorXd& V) const {
  Eigen::VectorXd g(m_);
  kinetic_gradient(eta.data(), V.data(), g);
  return g;
}

Vec3 InertiaInvariants::first_moment(const double* eta_data) const {
  const Eigen::Map<const Eigen::VectorXd> eta(eta_data, m_);
  Vec3 S = S0_ + S1_ * eta;
  for (int k = 0; k < m_; ++k)
    for (int l = 0; l < m_; ++l) S -= 0.5 * eta[k] * eta[l] * S2_[k * m_ + l];
  return S;
}

void InertiaInvariants::add_field_force(const double* eta, const Vec3& f, double* Q_data) const {
  Eigen::Map<Eigen::VectorXd> Q(Q_data, m_);
  Q.noalias() += S1_.transpose() * f;
  for (int k = 0; k < m_; ++k) Q.noalias() -= eta[k] * (E_[k].transpose() * f);
}

// B and C are built in M's blocks, so nothing is allocated.
void InertiaInvariants::mass_matrix(const double* eta_data, Eigen::Ref<Eigen::MatrixXd> M) const {
  const Eigen::Map<const Eigen::VectorXd> eta(eta_data, m_);
  Vec3 S = S0_ + S1_ * eta;
  auto B = M.topRightCorner(3, m_);
  auto C = M.block(3, 6, 3, m_);
  B = S1_;
  C = C0_;
  Mat3 J = J0_;
  for (int k = 0; k < m_; ++k) {
    B -= eta[k] * E_[k];
    J += eta[k] * J1_[k];
    C += eta[k] * C1_[k];
    for (int l = 0; l < m_; ++l) {
      const double kl = eta[k] * eta[l];
      S -= 0.5 * kl * S2_[k * m_ + l];
      J += kl * J2_[k * m_ + l];
    }
  }
  M.topLeftCorner<3, 3>() = mass_ * Mat3::Identity();
  M.block<3, 3>(0, 3) = -skew(S);
  M.block<3, 3>(3, 0) = skew(S);
  M.block<3, 3>(3, 3) = J;
  M.bottomLeftCorner(m_, 3) = B.transpose();
  M.block(6, 3, m_, 3) = C.transpose();
  M.bottomRightCorner(m_, m_) = Me_;
}

void InertiaInvariants::mass_matrix_rate(const double* eta_data, const double* eta_dot_data,
                                         Eigen::Ref<Eigen::MatrixXd> M) const {
  const Eigen::Map<const Eigen::VectorXd> eta(eta_data, m_), eta_dot(eta_dot_data, m_);
  M.setZero();
  Vec3 dS = S1_ * eta_dot;
  auto dB = M.topRightCorner(3, m_);
  auto dC = M.block(3, 6, 3, m_);
  Mat3 dJ = Mat3::Zero();
  for (int k = 0; k < m_; ++k) {
    dB -= eta_dot[k] * E_[k];
    dJ += eta_dot[k] * J1_[k];
    dC += eta_dot[k] * C1_[k];
    for (int l = 0; l < m_; ++l) {
      dS -= eta_dot[k] * eta[l] * S2_[k * m_ + l];
      dJ += (eta_dot[k] * eta[l] + eta[k] * eta_dot[l]) * J2_[k * m_ + l];
    }
  }
  M.block<3, 3>(0, 3) = -skew(dS);
  M.block<3, 3>(3, 0) = skew(dS);
  M.block<3, 3>(3, 3) = dJ;
  M.bottomLeftCorner(m_, 3) = dB.transpose();
  M.block(6, 3, m_, 3) = dC.transpose();
}

// d/d eta_k of T = (1/2) m v^2 - v^T S~ w + v^T B eta' + (1/2) w^T J w +
// w^T C eta' + (1/2) eta'^T Me eta' (S2's and J2's symmetric parts give
// the factors 2; J2_lk = J2_kl^T).
void InertiaInvariants::kinetic_gradient(const double* eta_data, const double* V,
                                         Eigen::Ref<Eigen::VectorXd> g) const {
  const Eigen::Map<const Eigen::VectorXd> eta(eta_data, m_), eta_dot(V + 6, m_);
  const Eigen::Map<const Vec3> v(V), w(V + 3);
  for (int k = 0; k < m_; ++k) {
    Vec3 dS = S1_.col(k);
    Mat3 dJ = 0.5 * J1_[k];
    for (int l = 0; l < m_; ++l) {
      dS -= eta[l] * S2_[k * m_ + l];
      dJ += eta[l] * J2_[k * m_ + l];
    }
    const Vec3 E_eta_dot = E_[k] * eta_dot, C_eta_dot = C1_[k] * eta_dot;
    g[k] = -v.dot(skew(dS) * w) - v.dot(E_eta_dot) + w.dot(dJ * w) + w.dot(C_eta_dot);
  }
}

}  // namespace unfurl::sim::flexible
