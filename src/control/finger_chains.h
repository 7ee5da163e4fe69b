#pragma once
// Forward kinematics and Jacobian of end-effectors over a set of moving joints, computed along
// each end-effector's chain of mobilizers without realizing the system (private to the control
// layer; used by FingertipIk's damped least squares).

#include "graspsim/system/multibody_model.h"

#include "graspsim/simbody.h"

#include <string>
#include <vector>

namespace graspsim::control {

/// The end-effectors' kinematics as functions of the moving joints' angles, everything else held.
class FingerChains {
public:
    /// @throws graspsim::InputError naming an unknown end-effector or a joint that cannot move.
    FingerChains(const system::MultibodyModel& model, const std::vector<std::string>& endEffectors,
                 const std::vector<std::string>& movingJoints);

    int getNumJoints() const { return static_cast<int>(joints_.size()); }
    int getNumEndEffectors() const { return static_cast<int>(chains_.size()); }
    /// The moving joints' mobilized bodies, in the given joint order.
    const std::vector<SimTK::MobilizedBodyIndex>& getMovingBodies() const { return movingBodies_; }
    /// Range of motion of moving joint k (rad or m); +-infinity when unlimited.
    double getLower(int k) const { return joints_[k].lower; }
    double getUpper(int k) const { return joints_[k].upper; }

    /// Reads, from `state` (any stage >= Model), the held joints and the moving joints' angles.
    void capture(const SimTK::State& state);
    /// The moving joints' angles captured from the state.
    const std::vector<double>& getCapturedAngles() const { return q0_; }

    /// End-effector locations p_GE (m, ground) for moving-joint angles q; with `jacobian`, also
    /// dp_GE/dq (row 3e+i is component i of end-effector e; columns in joint order).
    void calcLocations(const std::vector<double>& q, std::vector<SimTK::Vec3>& p_GE,
                       std::vector<double>* jacobian) const;

private:
    enum class Kind { Weld, Pin, Slider };
    struct Link {            // one mobilizer on an end-effector's path, base to tip
        Kind kind = Kind::Weld;
        SimTK::Transform X_PF, X_MB;
        int moving = -1;     // index among the moving joints, or -1 when held
        SimTK::MobilizedBodyIndex body;
    };
    struct Chain {
        SimTK::MobilizedBodyIndex base;  // parent of the first link; its pose does not depend on q
        std::vector<Link> links;
        SimTK::Vec3 p_BE;                // end-effector station on the last body (m)
    };
    struct MovingJoint { double lower, upper; };

    Chain makeChain(const SimTK::MobilizedBody& body, const SimTK::Vec3& p_BE, const std::string& name) const;

    const system::MultibodyModel& model_;
    std::vector<SimTK::MobilizedBodyIndex> movingBodies_;
    std::vector<MovingJoint> joints_;
    std::vector<Chain> chains_;
    std::vector<SimTK::Transform> X_GBase_;   // per chain, captured
    std::vector<std::vector<double>> heldQ_;  // per chain and link, captured (held links only)
    std::vector<double> q0_;
};

}  // namespace graspsim::control
