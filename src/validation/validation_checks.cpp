#include "graspsim/validation/validation_checks.h"

#include <algorithm>
#include <map>

namespace graspsim::validation {

namespace {

constexpr double kMm = 1000;                               // m -> mm, for the report only
constexpr double kDeg = 180.0 / 3.14159265358979323846;    // rad -> degree, for the report only

ValidationCheck makeCheck(const RunRecord& r, std::string name, double value, const std::string& relation, double bound,
                          std::string unit, std::string source) {
    bool pass = false;
    if (relation == "<=") pass = value <= bound;
    if (relation == ">=") pass = value >= bound;
    if (relation == "==") pass = value == bound;
    return {r.run.id, std::move(name), value, bound, std::move(unit), relation, pass, std::move(source)};
}

void checkFullRun(const RunRecord& r, std::vector<ValidationCheck>& checks) {
    checks.push_back(makeCheck(r, "run complete", r.summary.complete ? 1 : 0, "==", 1, "", "a run that stops early (bad input, divergence) gives no verdict"));
    if (r.run.options.perturbation != "none") return;
    checks.push_back(makeCheck(r, "held without perturbation", r.summary.held ? 1 : 0, "==", 1, "",
                               "thesis 4.1: Q_Th is the quality at which the object rests under gravity without slipping"));
    checks.push_back(makeCheck(r, "drift after settling", r.summary.objectDisplacement * kMm, "<=", kFullHoldDrift * kMm,
                               "mm", "a held object stays put: 5 mm, above the compliant skin settling into the grip (1-2.6 mm)"));
}

void checkApproxRun(const RunRecord& r, std::vector<ValidationCheck>& checks) {
    const simulation::SimulationSummary& s = r.summary;
    checks.push_back(makeCheck(r, "run complete", s.complete ? 1 : 0, "==", 1, "", "a run that stops early (bad input, divergence) gives no verdict"));
    checks.push_back(makeCheck(r, "engaged after the grasp settled", s.engaged && s.engageTime >= s.settleTime - 1e-9 ? 1 : 0,
                               "==", 1, "", "thesis 4.1: engage once Q >= Q_Th, a threshold taken from the settled grasp"));
    checks.push_back(makeCheck(r, "hold/slide verdict equals full contact's", s.held == r.referenceHeld ? 1 : 0, "==", 1, "",
                               "thesis 5.1: the approximation keeps or loses the object as full contact does"));
    // Both attachments: the pairs the approximation replaced (EngagedGraspTracker).
    if (s.engaged) {
        checks.push_back(makeCheck(r, "fingertip penetration growth while engaged", s.maxEngagedPenetrationGrowth * kMm, "<=",
                                   (r.referenceEngagedGrowth + kEngagedPenetrationGrowth) * kMm, "mm",
                                   "thesis conclusion: no fingertip sinking into the object while its contacts are off, "
                                   "beyond full contact's own growth of the same pads (the bound) by more than 0.1 mm, "
                                   "which is not visible"));
    }
    if (r.run.options.perturbation != "none" || !s.engaged) return;
    checks.push_back(makeCheck(r, "position error vs full contact, 2 s after engaging (max)", r.windowErrors.maxPosition * kMm,
                               "<=", kApproxPositionError * kMm, "mm",
                               "thesis 5.1: results similar to full contact; 2 mm, the order of the skin's compression"));
    checks.push_back(makeCheck(r, "orientation error vs full contact, 2 s after engaging (max)", r.windowErrors.maxAngle * kDeg,
                               "<=", kApproxAngleError * kDeg, "deg",
                               "thesis 5.1: results similar to full contact; 2 deg, not visible at hand scale"));
}

// The default full-contact run at the scenario's accuracy ("full", the reference of this pair: the
// linearly implicit stepper, resolveIntegrator) against the CVODE run at kReferenceAccuracy (the
// candidate): the error is the default integrator's.
void checkIntegrator(const RunRecord& r, std::vector<ValidationCheck>& checks) {
    checks.push_back(makeCheck(r, "run complete", r.summary.complete ? 1 : 0, "==", 1, "", "a run that stops early (bad input, divergence) gives no verdict"));
    checks.push_back(makeCheck(r, "default integrator vs CVODE reference: position error (max)", r.errors.maxPosition * kMm, "<=",
                               kIntegratorPositionError * kMm, "mm",
                               "a quarter of the approximation's 2 mm, so integration error cannot decide its check"));
    checks.push_back(makeCheck(r, "default integrator vs CVODE reference: orientation error (max)", r.errors.maxAngle * kDeg, "<=",
                               kIntegratorAngleError * kDeg, "deg",
                               "a quarter of the approximation's 2 deg, so integration error cannot decide its check"));
}

// Rigid against compliant contact, both full contact: the same verdict (both model Coulomb
// friction with the same coefficients), and the rigid run's own hold bound without perturbation.
void checkContactModel(const RunRecord& r, std::vector<ValidationCheck>& checks) {
    checks.push_back(makeCheck(r, "run complete", r.summary.complete ? 1 : 0, "==", 1, "", "a run that stops early (bad input, divergence) gives no verdict"));
    checks.push_back(makeCheck(r, "hold/slide verdict equals compliant contact's", r.summary.held == r.referenceHeld ? 1 : 0,
                               "==", 1, "",
                               "both contact models apply Coulomb friction with the same coefficients (thesis 2.1.5)"));
    if (r.run.options.perturbation != "none") return;
    checks.push_back(makeCheck(r, "drift after settling", r.summary.objectDisplacement * kMm, "<=", kFullHoldDrift * kMm, "mm",
                               "a held object stays put: 5 mm, above the compliant skin settling into the grip (1-2.6 mm)"));
}

void checkLongHold(const RunRecord& r, std::vector<ValidationCheck>& checks) {
    checks.push_back(makeCheck(r, "long hold complete (no NaN, no step collapse)", r.summary.complete ? 1 : 0, "==", 1, "",
                               "a long run stays finite and keeps stepping"));
    checks.push_back(makeCheck(r, "long hold drift after settling", r.summary.objectDisplacement * kMm, "<=",
                               kLongHoldDrift * kMm, "mm",
                               "below the held limits the attachment does not creep, so a minute-long hold stays put"));
}

std::map<int, double> findPairDepths(const simulation::ContactSample& sample, const std::vector<int>& pairs) {
    std::map<int, double> depths;
    for (const contact::ContactReport& c : sample.contacts) {
        if (!std::binary_search(pairs.begin(), pairs.end(), c.pairIndex)) continue;
        double& d = depths[c.pairIndex];
        d = std::max(d, c.depth);
    }
    return depths;
}

// The candidate's engaged spans, each from an engagement to the release after it (or the end).
double calcEngagedGrowth(const simulation::SimulationResult& reference, const simulation::SimulationResult& candidate) {
    const std::vector<int>& pairs = candidate.replacedPairs;
    double growth = 0, engagedAt = -1;
    for (const simulation::GraspEvent& e : candidate.events) {
        if (e.kind == simulation::GraspEventKind::Engage && engagedAt < 0) engagedAt = e.time;
        if (e.kind != simulation::GraspEventKind::Release || engagedAt < 0) continue;
        growth = std::max(growth, calcDepthGrowth(reference.contacts, pairs, engagedAt, e.time));
        engagedAt = -1;
    }
    if (engagedAt >= 0) growth = std::max(growth, calcDepthGrowth(reference.contacts, pairs, engagedAt, candidate.summary.simTime));
    return growth;
}

}  // namespace

double calcDepthGrowth(const std::vector<simulation::ContactSample>& contacts, const std::vector<int>& pairs, double from,
                       double to) {
    std::map<int, double> start;
    double growth = 0;
    for (const simulation::ContactSample& sample : contacts) {
        if (sample.time <= from) {
            start = findPairDepths(sample, pairs);
            continue;
        }
        if (sample.time > to) break;
        for (const auto& [pair, depth] : findPairDepths(sample, pairs)) {
            const auto before = start.find(pair);
            growth = std::max(growth, depth - (before == start.end() ? 0.0 : before->second));
        }
    }
    return growth;
}

void compareWithReference(const simulation::SimulationResult& reference, const simulation::SimulationResult& candidate,
                          RunRecord& record) {
    const simulation::SimulationSummary& s = candidate.summary;
    // The approximation from its engagement; another full-contact run from the start.
    const double from = s.engaged ? s.engageTime : (s.mode == simulation::SimulationMode::Full ? 0.0 : s.settleTime);
    record.hasReference = true;
    record.errors = comparePoses(reference.trajectory, candidate.trajectory, from, s.simTime);
    record.windowErrors = comparePoses(reference.trajectory, candidate.trajectory, from, from + kApproxWindow);
    record.referenceSlipOnset = findSlipOnset(reference.trajectory, reference.summary.settleTime, kSlipDistance);
    record.referenceHeld = reference.summary.held;
    record.referenceDisplacement = reference.summary.objectDisplacement;
    record.referenceEngagedGrowth = calcEngagedGrowth(reference, candidate);
}

std::vector<ValidationCheck> checkRun(const RunRecord& record) {
    std::vector<ValidationCheck> checks;
    if (record.run.longHold) {
        checkLongHold(record, checks);
    } else if (record.run.reference.empty()) {
        checkFullRun(record, checks);
    } else if (record.run.variant == "full-cvode") {
        checkIntegrator(record, checks);
    } else if (record.run.variant == "full-rigid") {
        checkContactModel(record, checks);
    } else {
        checkApproxRun(record, checks);
    }
    return checks;
}

}  // namespace graspsim::validation
