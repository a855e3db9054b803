// The Lie-group properties of testing/lie_group_suite.h on every group of geometry/: SO(3)
// (so3.h), SE(3) (se3.h), rigid motions in screw coordinates (screw.h) and unit dual quaternions
// (dual_quaternion.h). The screw and dual-quaternion charts are checked against se3.h's Jacobians
// and adjoint: se3::Log(T) = (θ l, θ m + d l) (screw.h) and Log of a unit dual quaternion is
// ½ (ω + ε v) (dual_quaternion.h), so the same twist coordinates must give the same derivatives.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "geometry/geometry_test_util.h"
#include "hecal/geometry/dual_quaternion.h"
#include "hecal/geometry/screw.h"
#include "hecal/geometry/se3.h"
#include "hecal/geometry/so3.h"
#include "testing/lie_group_suite.h"

namespace hecal {
namespace {

struct So3Group {
  using Element = Eigen::Matrix3d;
  using Tangent = Eigen::Vector3d;
  static constexpr int kDof = 3;
  static Element Exp(const Tangent& omega) { return so3::Exp(omega); }
  static Tangent Log(const Element& R) { return so3::Log(R); }
  static Element Compose(const Element& a, const Element& b) { return a * b; }
  static Element Inverse(const Element& R) { return R.transpose(); }
  static Element Identity() { return Element::Identity(); }
  static Eigen::Matrix3d Adjoint(const Element& R) { return so3::Adjoint(R); }
  static Eigen::Matrix3d RightJacobian(const Tangent& w) { return so3::RightJacobian(w); }
  static Eigen::Matrix3d LeftJacobian(const Tangent& w) { return so3::LeftJacobian(w); }
  static Eigen::Matrix3d RightJacobianInverse(const Tangent& w) {
    return so3::RightJacobianInverse(w);
  }
  static Eigen::Matrix3d LeftJacobianInverse(const Tangent& w) {
    return so3::LeftJacobianInverse(w);
  }
  static double Distance(const Element& a, const Element& b) { return MaxAbs(a - b); }
  static constexpr double kExpLog = 2e-15;
  static constexpr double kLogExpRotation = 2e-15;
  static constexpr double kLogExpTranslation = 0.0;
  static constexpr double kGroup = 2e-15;
  static constexpr double kJacobian = 1e-11;
  static constexpr double kInverseJacobian = 1e-10;
};

// The SE(3) Jacobians, adjoint and pose operations shared by the three charts of rigid motions.
struct RigidMotions {
  using Tangent = Vector6d;
  static constexpr int kDof = 6;
  static Matrix6d RightJacobian(const Tangent& xi) { return se3::RightJacobian(xi); }
  static Matrix6d LeftJacobian(const Tangent& xi) { return se3::LeftJacobian(xi); }
  static Matrix6d RightJacobianInverse(const Tangent& xi) { return se3::RightJacobianInverse(xi); }
  static Matrix6d LeftJacobianInverse(const Tangent& xi) { return se3::LeftJacobianInverse(xi); }
};

struct Se3Group : RigidMotions {
  using Element = Pose;
  static Element Exp(const Tangent& xi) { return se3::Exp(xi); }
  static Tangent Log(const Element& T) { return se3::Log(T); }
  static Element Compose(const Element& a, const Element& b) { return a * b; }
  static Element Inverse(const Element& T) { return T.inverse(); }
  static Element Identity() { return Pose::Identity(); }
  static Matrix6d Adjoint(const Element& T) { return se3::Adjoint(T); }
  static double Distance(const Element& a, const Element& b) {
    return MaxAbs(a.matrix() - b.matrix());
  }
  static constexpr double kExpLog = 1e-14;
  static constexpr double kLogExpRotation = 2e-15;
  static constexpr double kLogExpTranslation = 4e-15;
  static constexpr double kGroup = 4e-14;
  static constexpr double kJacobian = 1e-10;
  static constexpr double kInverseJacobian = 1e-9;
};

// Poses in screw coordinates: Exp(ξ) = PoseFromScrew of the screw with θ l = ω and
// θ m + d l = v (screw.h), Log the twist of ScrewFromPose.
struct ScrewChart : Se3Group {
  static Screw ScrewOfTwist(const Tangent& xi) {
    Screw screw;
    const Eigen::Vector3d omega = xi.head<3>(), v = xi.tail<3>();
    screw.theta = omega.norm();
    if (screw.theta > 0.0) {
      screw.l = omega / screw.theta;
      screw.d = screw.l.dot(v);
      screw.m = (v - screw.d * screw.l) / screw.theta;
    } else if (v.norm() > 0.0) {  // a pure translation (screw.h)
      screw.l = v.normalized();
      screw.d = v.norm();
    }
    return screw;
  }
  static Element Exp(const Tangent& xi) { return PoseFromScrew(ScrewOfTwist(xi)); }
  static Tangent Log(const Element& T) {
    const Screw screw = ScrewFromPose(T);
    Tangent xi;
    xi << screw.theta * screw.l, screw.theta * screw.m + screw.d * screw.l;
    return xi;
  }
  static constexpr double kExpLog = 1e-14;
  static constexpr double kLogExpRotation = 4e-15;
  static constexpr double kLogExpTranslation = 1e-14;
};

struct DualQuaternionGroup : RigidMotions {
  using Element = DualQuaternion;
  static Element Exp(const Tangent& xi) {
    const Eigen::Vector3d w = 0.5 * xi.head<3>(), v = 0.5 * xi.tail<3>();
    return DualQuaternion(Eigen::Quaterniond(0.0, w.x(), w.y(), w.z()),
                          Eigen::Quaterniond(0.0, v.x(), v.y(), v.z()))
        .Exp();
  }
  static Tangent Log(const Element& q) {
    const DualQuaternion log = q.Log();
    Tangent xi;
    xi << 2.0 * log.real().vec(), 2.0 * log.dual().vec();
    return xi;
  }
  static Element Compose(const Element& a, const Element& b) { return a * b; }
  static Element Inverse(const Element& q) { return q.Conjugate(); }
  static Element Identity() { return DualQuaternion::Identity(); }
  static Matrix6d Adjoint(const Element& q) { return se3::Adjoint(q.ToPose()); }
  static double Distance(const Element& a, const Element& b) {
    return MaxAbs(a.ToMatrix() - b.ToMatrix());
  }
  static constexpr double kExpLog = 1e-14;
  static constexpr double kLogExpRotation = 4e-15;
  static constexpr double kLogExpTranslation = 1e-14;
  static constexpr double kGroup = 4e-14;
  static constexpr double kJacobian = 1e-10;
  static constexpr double kInverseJacobian = 1e-9;
};

using Groups = ::testing::Types<So3Group, Se3Group, ScrewChart, DualQuaternionGroup>;

}  // namespace

namespace testing {
INSTANTIATE_TYPED_TEST_SUITE_P(Geometry, LieGroupTest, Groups);
}  // namespace testing
}  // namespace hecal
