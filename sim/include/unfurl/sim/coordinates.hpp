// The two coordinate spaces of the state, with index types of their own so
// that one cannot index the other:
// - positions q (Model::nq): a joint's m_i numbers (a quaternion has four);
// - velocity coordinates w (Model::nv): a joint's n_i rates, the momenta p
//   conjugate to them, and the generalized forces Q.
// For a revolute or prismatic joint w is q', but the two arrays differ in
// length and order as soon as a ball or free joint appears.
#pragma once

namespace unfurl::sim {

struct PositionIndex {
  int value = -1;
  bool valid() const { return value >= 0; }
  PositionIndex operator+(int k) const { return {value + k}; }
};

struct VelocityIndex {
  int value = -1;
  bool valid() const { return value >= 0; }
  VelocityIndex operator+(int k) const { return {value + k}; }
};

// Views of a positions array and of a velocity-coordinate array (rates,
// momenta or generalized forces), indexed only by their own kind; T is
// `const double` for a read-only view.
template <class Index, class T>
class CoordinateArray {
 public:
  explicit CoordinateArray(T* x) : x_(x) {}
  T& operator[](Index i) const { return x_[i.value]; }
  T* at(Index i) const { return x_ + i.value; }
  T* data() const { return x_; }

 private:
  T* x_;
};

using Positions = CoordinateArray<PositionIndex, const double>;
using Rates = CoordinateArray<VelocityIndex, const double>;
using RatesOut = CoordinateArray<VelocityIndex, double>;

}  // namespace unfurl::sim
