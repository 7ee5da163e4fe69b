#pragma once
/// @file
/// What the grasp approximation keeps watching of the finger-object contacts while one
/// constraint, not the contacts, holds the object (thesis chapter 4: "the simulation
/// continues to monitor the contacts between the hand and object, but without solving the
/// dynamical equations").
///
/// TRACKED CONTACTS. At engagement every finger-object contact carrying force is captured: its
/// point as a station of the palm H (the fingers are locked to it while engaged, so the point
/// moves with the hand), its force on the object and its normal into the object, both expressed
/// in O. While engaged, contact i is at p_GC_i = X_GH p_HC_i with normal R_GO n_O_i: the face it
/// pressed at engagement, even where the palm-fixed point now lies nearer another face.
///
/// QUALITY WHILE ENGAGED (calcQuality). The contact pairs are off, so there are no contact forces
/// to build Q from. Instead the constraint's wrench on the object (LimitedWeld::findWrench or
/// LimitedBushing::findWrench, moved to O's origin) is distributed over the tracked contacts by
/// grasp::distributeWrench: the forces inside the (static) friction cones that reproduce it and
/// stay closest to the forces captured at engagement. The reference keeps the squeeze of the
/// locked fingers, which the wrench cannot show (it lies in the grasp map's null space); only the
/// change of the load since engagement is spread (least norm). Q is then grasp::calcGraspQuality
/// of the tracked contacts with those normal forces, exactly as the full-contact Q is built from
/// the contact solver's normal forces (contact_grasp_quality.h): at engagement the two agree, and
/// a load that pulls the object away from a finger unloads that contact and lowers Q. Not
/// modelled: the squeeze does not follow a slide of the object (the fingers are locked), and a
/// wrench direction the contacts cannot produce within friction is ignored (reported as
/// residual by distributeWrench; the slide test catches the resulting motion).
///
/// PENETRATION WHILE ENGAGED (measurePenetration). The contact pairs the approximation has
/// switched off (all with merged; the attached fingers' with multi) are evaluated as if on
/// (CompliantContactForce::findContactDepths of a list: the geometry alone, nothing applied, the
/// state untouched): the depth of every such pair in contact. Pairs still in
/// ordinary contact are not counted: their compression under a load is the compliant model's, as
/// in full contact. What is bounded: the GROWTH of each pair's depth beyond its depth at
/// engagement (a new contact counts with its whole depth). What is not: the depth the
/// grasp has at engagement, the compliant skin's compression under the grip (1-2.6 mm at the
/// scenarios' 5e5 Pa), which the locked fingers keep while engaged and which full contact has
/// too; it is reported (PenetrationStats::atEngage) but is not interpenetration caused by the
/// approximation. Sampled at the switch's checks (every ik_interval) and at the output samples.

#include "graspsim/contact/compliant_contact_force.h"
#include "graspsim/simulation/approximation_context.h"

#include "graspsim/simbody.h"

#include <map>
#include <vector>

namespace graspsim::simulation {

/// Penetration of the tracked fingers into the object while engaged (m).
struct PenetrationStats {
    double atEngage = 0;         ///< deepest contact at the (last) engagement
    double maxWhileEngaged = 0;  ///< deepest contact seen while engaged (all engagements)
    double maxGrowth = 0;        ///< largest growth of one contact's depth beyond its depth at engagement
    std::vector<int> replacedPairs;  ///< contact pairs switched off while engaged (all engagements), ascending
};

/// The tracked contacts of the current engagement and the penetration seen so far.
class EngagedGraspTracker {
public:
    /// @param context the approximation's view of the scene; must outlive the tracker and its copies.
    explicit EngagedGraspTracker(const ApproximationContext& context);

    /// Captures the contacts of `reports` (those with normal force > 0) as the tracked contacts.
    /// Needs Stage::Position; `reports` from `state`.
    void capture(const SimTK::State& state, const std::vector<contact::ContactReport>& reports);
    /// Number of tracked contacts.
    int getNumContacts() const { return static_cast<int>(tracked_.size()); }

    /// Q (N) from the engaged constraint's wrench on the object, distributed over the tracked
    /// contacts (file comment). 0 with no tracked contacts. Realizes `state` to
    /// Stage::Acceleration with the weld (its reaction is a Lagrange multiplier), to
    /// Stage::Velocity with the bushing.
    double calcQuality(const SimTK::State& state) const;
    /// The largest growth (m) of a switched-off pair's depth beyond its depth at engagement, now,
    /// evaluated as if the pairs were on, and updates getPenetration(). Used by both attachments.
    /// Realizes `state` to Stage::Position.
    double measurePenetration(const SimTK::State& state);
    const PenetrationStats& getPenetration() const { return penetration_; }

private:
    struct TrackedContact {
        SimTK::Vec3 p_HC;  // contact point on the palm (m)
        SimTK::Vec3 f_O;   // contact force on the object at engagement, in O (N)
        SimTK::Vec3 n_O;   // the contact's normal at engagement, into the object, in O
    };
    SimTK::SpatialVec findConstraintWrench(const SimTK::State& state) const;

    const ApproximationContext* context_;  // a pointer, so that the tracker copies and assigns as part of a State
    std::vector<TrackedContact> tracked_;
    std::map<int, double> depthAtEngage_;  // by contact pair index (m)
    PenetrationStats penetration_;
};

}  // namespace graspsim::simulation
