#pragma once
/// @file
/// What the grasp approximation (grasp_switch.h, multi_attachment_switch.h,
/// engaged_grasp_tracker.h) uses of the scene it runs on, gathered once when it is built
/// (grasp_approximation.h): references to the scene's Simbody elements and plain values of its
/// scenario. The approximation holds this, never the scene, so that nothing calls back up into
/// the scene.

#include "graspsim/contact/compliant_contact_force.h"
#include "graspsim/contact/contact_parameters.h"
#include "graspsim/control/grasp_controller.h"
#include "graspsim/grasp/grasp_attachment.h"
#include "graspsim/grasp/multi_attachment.h"
#include "graspsim/scenario/scenario.h"
#include "graspsim/simulation/fingertip_goals.h"
#include "graspsim/simulation/object_hold.h"
#include "graspsim/system/implicit_joint_impedance.h"
#include "graspsim/system/multibody_model.h"

#include "graspsim/simbody.h"

#include <vector>

namespace graspsim::simulation {

/// The scene as the approximation sees it. Every reference is to an element of the scene, which
/// must outlive the approximation.
struct ApproximationContext {
    const system::MultibodyModel& model;         ///< the system, its matter and end-effectors
    const SimTK::MobilizedBody& object;          ///< the object; its frame O at its centre of mass
    const SimTK::MobilizedBody& palm;            ///< the palm H, the merged constraint's frame F's body
    std::vector<SimTK::MobilizedBodyIndex> fingerMobilizers;  ///< locked to merge the hand
    const contact::CompliantContactForce& contacts;  ///< the finger-object contact pairs
    contact::ContactParameters contactParameters;    ///< the pairs' friction and sticking speed
    SimTK::Vec3 gravity_G;                       ///< the scenario's gravity, in Ground (m/s^2)
    const FingertipGoals& goals;                 ///< goal end-effectors and their surface points
    ObjectHold hold;                             ///< the object's hold until its release
    double settleTime = 0;                       ///< when the grasp counts as settled (s)
    double heldTolerance = 0;                    ///< fingertip-goal distance that still counts as held (m)
    const grasp::GraspAttachment& attachment;    ///< the attachment, whichever realizes it
    const grasp::MultiAttachment* multi = nullptr;  ///< the same, when it is the multi-attachment
    const control::GraspController& controller;  ///< the IK controller the switch runs while ungrasped
    double ikInterval = 0;                       ///< the IK's period, the switch's too (s)
    /// Every joint's stiffness (springs + PD) and stop, for the fingers' compliance
    /// (finger_compliance.h) of the compliance limits.
    std::vector<system::JointImpedance> jointImpedances;
};

}  // namespace graspsim::simulation
