#pragma once
// OMPL's view of one of our scenes, shared by the benchmarks that race OMPL's planners (prm,
// rrt, lazy): its state space for our robot's C-space, our checker as its validity checker
// (counted), and the same edge-check resolution. Include it only where CSPACELAB_WITH_OMPL is
// defined (tests/bench/CMakeLists.txt defines it natively when Debian's libompl-dev is found).
//
// The spaces, by robot (robot_kind()):
//   point     R^2: RealVectorStateSpace(2) over the workspace box (the same metric as ours);
//   arm       T^N: a compound of N SO2StateSpace, weight 1 each;
//   polygon   SE(2): SE2StateSpace over the workspace box, its angle weighted by the polygon's
//             radius (our SE(2) weights the angle so too).
// A compound space's distance is OMPL's weighted *sum* of its parts' distances, where ours is
// their Euclidean norm: OMPL's distance is never shorter than ours, so a resolution D in OMPL's
// metric steps never farther than D in ours, and OMPL tests at least as many configurations along
// an edge (on R^2 exactly the same ones). Both sides take the same D and the same range (RRT's)
// as numbers.
#include <memory>
#include <stdexcept>

#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateValidityChecker.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/spaces/SO2StateSpace.h>

#include "core/checking/collision.hpp"
#include "core/robots/robot.hpp"

namespace bench {

namespace ob = ompl::base;

/// A state of the space made by ompl_space() for `kind`, read as our configuration, and back.
inline csl::Config ompl_config(csl::RobotKind kind, int dof, const ob::State* s) {
  csl::Config q(dof);
  switch (kind) {
    case csl::RobotKind::Point: {
      const auto* v = s->as<ob::RealVectorStateSpace::StateType>();
      q[0] = v->values[0];
      q[1] = v->values[1];
      break;
    }
    case csl::RobotKind::Arm: {
      const auto* c = s->as<ob::CompoundStateSpace::StateType>();
      for (int i = 0; i < dof; ++i) q[i] = c->as<ob::SO2StateSpace::StateType>(static_cast<unsigned>(i))->value;
      break;
    }
    case csl::RobotKind::RigidPolygon: {
      const auto* se2 = s->as<ob::SE2StateSpace::StateType>();
      q[0] = se2->getX();
      q[1] = se2->getY();
      q[2] = se2->getYaw();
      break;
    }
  }
  return q;
}

inline void ompl_state(csl::RobotKind kind, const csl::Config& q, ob::State* s) {
  switch (kind) {
    case csl::RobotKind::Point: {
      auto* v = s->as<ob::RealVectorStateSpace::StateType>();
      v->values[0] = q[0];
      v->values[1] = q[1];
      break;
    }
    case csl::RobotKind::Arm: {
      auto* c = s->as<ob::CompoundStateSpace::StateType>();
      for (Eigen::Index i = 0; i < q.size(); ++i)
        c->as<ob::SO2StateSpace::StateType>(static_cast<unsigned>(i))->value = q[i];
      break;
    }
    case csl::RobotKind::RigidPolygon: {
      auto* se2 = s->as<ob::SE2StateSpace::StateType>();
      se2->setXY(q[0], q[1]);
      se2->setYaw(q[2]);
      break;
    }
  }
}

/// OMPL's state space for our world's C-space (see the table above).
inline ob::StateSpacePtr ompl_space(const csl::CollisionWorld& world) {
  const csl::Space& space = world.space();
  switch (csl::robot_kind(world.robot())) {
    case csl::RobotKind::Point: {
      auto plane = std::make_shared<ob::RealVectorStateSpace>(2);
      ob::RealVectorBounds bounds(2);
      for (int i = 0; i < 2; ++i) {
        bounds.setLow(static_cast<unsigned>(i), space.coordinate(i).lo);
        bounds.setHigh(static_cast<unsigned>(i), space.coordinate(i).hi);
      }
      plane->setBounds(bounds);
      return plane;
    }
    case csl::RobotKind::Arm: {
      auto torus = std::make_shared<ob::CompoundStateSpace>();
      for (int i = 0; i < space.dim(); ++i) torus->addSubspace(std::make_shared<ob::SO2StateSpace>(), 1.0);
      return torus;
    }
    case csl::RobotKind::RigidPolygon: {
      auto se2 = std::make_shared<ob::SE2StateSpace>();
      ob::RealVectorBounds bounds(2);
      for (int i = 0; i < 2; ++i) {
        bounds.setLow(static_cast<unsigned>(i), space.coordinate(i).lo);
        bounds.setHigh(static_cast<unsigned>(i), space.coordinate(i).hi);
      }
      se2->setBounds(bounds);
      se2->setSubspaceWeight(1, space.coordinate(2).weight);  // SE2StateSpace's default is 0.5
      return se2;
    }
  }
  throw std::logic_error("no OMPL space for this robot");
}

/// Our CollisionWorld::is_free as OMPL's validity checker, counting the states it tests (a
/// sample, a configuration along an edge: OMPL's collision checks).
class CountingChecker : public ob::StateValidityChecker {
 public:
  CountingChecker(const ob::SpaceInformationPtr& si, const csl::CollisionWorld& world)
      : ob::StateValidityChecker(si),
        world_(world),
        kind_(csl::robot_kind(world.robot())),
        dof_(world.space().dim()) {}
  bool isValid(const ob::State* s) const override {
    ++checks_;
    return world_.is_free(ompl_config(kind_, dof_, s));
  }
  long checks() const { return checks_; }

 private:
  const csl::CollisionWorld& world_;
  csl::RobotKind kind_;
  int dof_;
  mutable long checks_ = 0;
};

/// OMPL's space information over our world: its space, our checker, and the edge-check
/// resolution `resolution` (an absolute D, in OMPL's metric: OMPL takes it as a fraction of its
/// space's extent). Not copyable: the checker lives as long as the space information.
class OmplScene {
 public:
  OmplScene(const csl::CollisionWorld& world, double resolution) : kind_(csl::robot_kind(world.robot())) {
    const ob::StateSpacePtr space = ompl_space(world);
    si_ = std::make_shared<ob::SpaceInformation>(space);
    checker_ = std::make_shared<CountingChecker>(si_, world);
    si_->setStateValidityChecker(checker_);
    si_->setStateValidityCheckingResolution(resolution / space->getMaximumExtent());
    si_->setup();
  }
  OmplScene(const OmplScene&) = delete;
  OmplScene& operator=(const OmplScene&) = delete;

  const ob::SpaceInformationPtr& si() const { return si_; }
  /// States tested so far (all planners on this scene).
  long checks() const { return checker_->checks(); }
  void to_state(const csl::Config& q, ob::State* s) const { ompl_state(kind_, q, s); }

 private:
  csl::RobotKind kind_;
  ob::SpaceInformationPtr si_;
  std::shared_ptr<CountingChecker> checker_;
};

}  // namespace bench
