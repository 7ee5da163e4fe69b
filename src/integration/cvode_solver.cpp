#include "cvode_solver.h"

#include "graspsim/error.h"

#include <cvode/cvode_ls.h>
#include <cvode/cvode_proj.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

namespace graspsim::integration {

namespace {

void copyToState(N_Vector from, SimTK::Vector& to) {
    const realtype* y = N_VGetArrayPointer(from);
    for (int i = 0; i < to.size(); ++i) to[i] = y[i];
}

void copyFromState(const SimTK::Vector& from, N_Vector to) {
    realtype* y = N_VGetArrayPointer(to);
    for (int i = 0; i < from.size(); ++i) y[i] = from[i];
}

CvodeCallbackContext& contextOf(void* data) { return *static_cast<CvodeCallbackContext*>(data); }

// Puts CVODE's trial time and y into the scratch state.
SimTK::State& loadWorkState(CvodeCallbackContext& c, realtype t, N_Vector y) {
    c.work.updTime() = t;
    copyToState(y, c.work.updY());
    return c.work;
}

// ẏ = f(t, y). A Simbody failure (e.g. a singular constraint Jacobian) is reported as

// A callback's exception for the failure message: Simbody's own text without the source-file
// header its what() starts with, on one line.
std::string describeCallbackError(const std::exception& e) {
    const auto* simbody = dynamic_cast<const SimTK::Exception::Base*>(&e);
    return foldToOneLine(simbody ? simbody->getMessageText() : e.what());
}

// recoverable: CVODE then retries with a smaller step.
int evaluateRhs(realtype t, N_Vector y, N_Vector ydot, void* data) {
    CvodeCallbackContext& c = contextOf(data);
    try {
        SimTK::State& s = loadWorkState(c, t, y);
        c.system->realize(s, SimTK::Stage::Acceleration);
        copyFromState(s.getYDot(), ydot);
        return 0;
    } catch (const std::exception& e) {
        c.lastCallbackError = describeCallbackError(e);
        return 1;
    }
}

// The event triggers are the root functions, in the State's order.
int evaluateTriggers(realtype t, N_Vector y, realtype* g, void* data) {
    CvodeCallbackContext& c = contextOf(data);
    try {
        SimTK::State& s = loadWorkState(c, t, y);
        c.system->realize(s, c.triggerStage);
        // State::getEventTriggers() needs Acceleration; by stage, realizing only as far as the
        // triggers need.
        for (SimTK::Stage stage = SimTK::Stage::Time; stage <= c.triggerStage; stage = stage.next()) {
            const SimTK::Vector& triggers = s.getEventTriggersByStage(stage);
            const int start = s.getEventTriggerStartByStage(stage);
            for (int k = 0; k < triggers.size(); ++k) g[start + k] = triggers[k];
        }
        return 0;
    } catch (const std::exception& e) {
        c.lastCallbackError = describeCallbackError(e);
        return -1;
    }
}

// Projects the part of `err` (CVODE's local error estimate) that belongs to `part` (q or u),
// together with the state, so that the error test judges only the error along the manifold.
SimTK::Vector extractPart(N_Vector err, int offset, int size) {
    SimTK::Vector part(err ? size : 0);
    if (err) for (int i = 0; i < size; ++i) part[i] = NV_Ith_S(err, offset + i);
    return part;
}

void storePart(const SimTK::Vector& part, int offset, N_Vector err) {
    for (int i = 0; i < part.size(); ++i) NV_Ith_S(err, offset + i) = part[i];
}

// Applies prescribed motion and projects q, then u, onto the constraint manifold (the order
// Simbody's own integrators use: u's constraints depend on q).
bool projectState(CvodeCallbackContext& c, SimTK::State& s, N_Vector err) {
    SimTK::ProjectOptions options(c.constraintTolerance);
    options.setOption(SimTK::ProjectOptions::LocalOnly);
    options.setOption(SimTK::ProjectOptions::DontThrow);
    SimTK::ProjectResults results;
    c.system->realize(s, SimTK::Stage::Time);
    c.system->prescribeQ(s);
    c.system->realize(s, SimTK::Stage::Position);
    SimTK::Vector qErr = extractPart(err, 0, s.getNQ());
    c.system->projectQ(s, qErr, options, results);
    if (results.getExitStatus() != SimTK::ProjectResults::Succeeded) return false;
    c.system->prescribeU(s);
    c.system->realize(s, SimTK::Stage::Velocity);
    SimTK::Vector uErr = extractPart(err, s.getNQ(), s.getNU());
    c.system->projectU(s, uErr, options, results);
    if (results.getExitStatus() != SimTK::ProjectResults::Succeeded) return false;
    if (err) {
        storePart(qErr, 0, err);
        storePart(uErr, s.getNQ(), err);
    }
    return true;
}

// CVODE's projection hook: corr = P(ycur) - ycur. CVODE's epsProj (a bound on the correction in
// its error-weighted norm) is not used: Simbody's projection works to the constraint tolerance,
// a physically meaningful accuracy on the constraint errors themselves.
int projectOntoManifold(realtype t, N_Vector ycur, N_Vector corr, realtype /*epsProj*/, N_Vector err, void* data) {
    CvodeCallbackContext& c = contextOf(data);
    try {
        SimTK::State& s = loadWorkState(c, t, ycur);
        if (!projectState(c, s, err)) return 1;  // recoverable: CVODE retries with a smaller step
        const SimTK::Vector& y = s.getY();
        for (int i = 0; i < y.size(); ++i) NV_Ith_S(corr, i) = y[i] - NV_Ith_S(ycur, i);
        return 0;
    } catch (const std::exception& e) {
        c.lastCallbackError = describeCallbackError(e);
        return -1;
    }
}

// CVODE's messages (warnings and errors) are kept for the exception text instead of stderr.
void keepCvodeMessage(int /*code*/, const char* module, const char* function, char* message, void* data) {
    contextOf(data).lastCvodeMessage = std::string(module) + "::" + function + ": " + message;
}

std::string flagName(int flag) {
    char* name = CVodeGetReturnFlagName(flag);
    std::string text = name ? name : "unknown flag " + std::to_string(flag);
    std::free(name);
    return text;
}

SimTK::Stage findTriggerStage(const SimTK::State& s) {
    SimTK::Stage highest = SimTK::Stage::Empty;
    for (SimTK::Stage g = SimTK::Stage::Time; g <= SimTK::Stage::Report; g = g.next()) {
        if (s.getNEventTriggersByStage(g) > 0) highest = g;
    }
    return highest;
}

}  // namespace

CvodeSolver::CvodeSolver(const SimTK::System& system, const CvodeOptions& options, double constraintTolerance)
    : options_(options) {
    context_.system = &system;
    context_.constraintTolerance = constraintTolerance;
    check("SUNContext_Create", SUNContext_Create(nullptr, &sunContext_));
}

CvodeSolver::~CvodeSolver() {
    destroy();
    SUNContext_Free(&sunContext_);
}

void CvodeSolver::destroy() {
    if (cvode_) CVodeFree(&cvode_);
    if (linearSolver_) SUNLinSolFree(linearSolver_);
    if (jacobian_) SUNMatDestroy(jacobian_);
    if (y_) N_VDestroy(y_);
    if (absoluteTolerance_) N_VDestroy(absoluteTolerance_);
    cvode_ = nullptr;
    linearSolver_ = nullptr;
    jacobian_ = nullptr;
    y_ = absoluteTolerance_ = nullptr;
}

void CvodeSolver::check(const std::string& call, int flag) const {
    if (flag < 0) fail(call, flag, context_.work.getTime());
}

void CvodeSolver::fail(const std::string& call, int flag, double t) const {
    std::string text = "CVODE " + call + " failed at t = " + std::to_string(t) + " s: " + flagName(flag);
    if (!context_.lastCvodeMessage.empty()) text += " (" + context_.lastCvodeMessage + ")";
    if (!context_.lastCallbackError.empty()) text += "; last Simbody error: " + context_.lastCallbackError;
    throw NumericalError(text);
}

// BDF with Newton iteration on a dense finite-difference Jacobian: the stiff compliant-contact
// case needs the implicit method, and the systems here are small enough for dense algebra.
void CvodeSolver::create(int ny) {
    destroy();
    ny_ = ny;
    y_ = N_VNew_Serial(ny, sunContext_);
    absoluteTolerance_ = N_VNew_Serial(ny, sunContext_);
    copyFromState(context_.work.getY(), y_);
    cvode_ = CVodeCreate(CV_BDF, sunContext_);
    if (!cvode_ || !y_ || !absoluteTolerance_) throw NumericalError("CVODE: out of memory creating the solver");
    check("CVodeInit", CVodeInit(cvode_, evaluateRhs, context_.work.getTime(), y_));
    check("CVodeSetUserData", CVodeSetUserData(cvode_, &context_));
    check("CVodeSetErrHandlerFn", CVodeSetErrHandlerFn(cvode_, keepCvodeMessage, &context_));
    jacobian_ = SUNDenseMatrix(ny, ny, sunContext_);
    linearSolver_ = SUNLinSol_Dense(y_, jacobian_, sunContext_);
    check("CVodeSetLinearSolver", CVodeSetLinearSolver(cvode_, linearSolver_, jacobian_));
    check("CVodeSetMaxOrd", CVodeSetMaxOrd(cvode_, options_.maxOrder));
    check("CVodeSetMaxNumSteps", CVodeSetMaxNumSteps(cvode_, options_.maxStepsPerInterval));
    if (options_.maxStepSize > 0) check("CVodeSetMaxStep", CVodeSetMaxStep(cvode_, options_.maxStepSize));
    if (options_.projection) check("CVodeSetProjFn", CVodeSetProjFn(cvode_, projectOntoManifold));
}

void CvodeSolver::start(const SimTK::State& s) {
    context_.work = s;
    context_.lastCallbackError.clear();
    context_.lastCvodeMessage.clear();
    if (s.getNY() != ny_) {
        if (cvode_) foldCurrentCounts();
        create(s.getNY());
    } else {
        foldCurrentCounts();
        copyFromState(s.getY(), y_);
        check("CVodeReInit", CVodeReInit(cvode_, s.getTime(), y_));
    }
    setTolerances(s);
    setTriggers(s);
}

// atol_i = atol / (unit weight of y_i): see cvode_integrator.h.
void CvodeSolver::setTolerances(const SimTK::State& s) {
    const double rtol = options_.relativeTolerance;
    const double atol = options_.absoluteTolerance > 0 ? options_.absoluteTolerance : rtol;
    const int nq = s.getNQ(), nu = s.getNU();
    const SimTK::Vector& wu = s.getUWeights();
    const SimTK::Vector& wz = s.getZWeights();
    for (int i = 0; i < ny_; ++i) {
        const double weight = i < nq ? 1.0 : i < nq + nu ? wu[i - nq] : wz[i - nq - nu];
        NV_Ith_S(absoluteTolerance_, i) = weight > 0 ? atol / weight : atol;
    }
    check("CVodeSVtolerances", CVodeSVtolerances(cvode_, rtol, absoluteTolerance_));
}

// Root directions from EventTriggerInfo: +1 rising only, -1 falling only, 0 both.
void CvodeSolver::setTriggers(const SimTK::State& s) {
    const int n = s.getNEventTriggers();
    context_.triggerStage = findTriggerStage(s);
    context_.system->calcEventTriggerInfo(s, triggerInfo_);
    check("CVodeRootInit", CVodeRootInit(cvode_, n, n > 0 ? evaluateTriggers : nullptr));
    if (n == 0) return;
    std::vector<int> directions(n, 0);
    for (int i = 0; i < n; ++i) {
        const bool rising = triggerInfo_[i].shouldTriggerOnRisingSignTransition();
        const bool falling = triggerInfo_[i].shouldTriggerOnFallingSignTransition();
        directions[i] = rising == falling ? 0 : rising ? 1 : -1;
    }
    check("CVodeSetRootDirection", CVodeSetRootDirection(cvode_, directions.data()));
    check("CVodeSetNoInactiveRootWarn", CVodeSetNoInactiveRootWarn(cvode_));
}

bool CvodeSolver::advance(double tStop, SimTK::State& s) {
    check("CVodeSetStopTime", CVodeSetStopTime(cvode_, tStop));
    realtype reached = s.getTime();
    const int flag = CVode(cvode_, tStop, y_, &reached, CV_NORMAL);
    if (flag < 0) {
        realtype t = reached;
        CVodeGetCurrentTime(cvode_, &t);
        fail("CVode", flag, t);
    }
    s.updTime() = reached;
    copyToState(y_, s.updY());
    return flag == CV_ROOT_RETURN;
}

SimTK::Array_<SimTK::EventId> CvodeSolver::findTriggeredEvents() const {
    std::vector<int> found(triggerInfo_.size(), 0);
    SimTK::Array_<SimTK::EventId> events;
    if (found.empty() || CVodeGetRootInfo(cvode_, found.data()) < 0) return events;
    for (std::size_t i = 0; i < found.size(); ++i) {
        if (found[i] != 0) events.push_back(triggerInfo_[i].getEventId());
    }
    return events;
}

// CVodeReInit zeroes CVODE's counters: bank them first.
void CvodeSolver::foldCurrentCounts() { addCurrentCountsTo(totals_); }

void CvodeSolver::addCurrentCountsTo(IntegrationStatistics& out) const {
    if (!cvode_) return;
    long steps = 0, rhs = 0, setups = 0, errorFails = 0, jacobians = 0, rhsForJacobian = 0;
    long solveFails = 0, projections = 0, roots = 0, iterations = 0;
    CVodeGetNumSteps(cvode_, &steps);
    CVodeGetNumRhsEvals(cvode_, &rhs);
    CVodeGetNumLinSolvSetups(cvode_, &setups);
    CVodeGetNumErrTestFails(cvode_, &errorFails);
    CVodeGetNumJacEvals(cvode_, &jacobians);
    CVodeGetNumLinRhsEvals(cvode_, &rhsForJacobian);
    CVodeGetNumStepSolveFails(cvode_, &solveFails);
    if (options_.projection) CVodeGetNumProjEvals(cvode_, &projections);
    CVodeGetNumGEvals(cvode_, &roots);
    CVodeGetNumNonlinSolvIters(cvode_, &iterations);
    out.steps += steps;
    out.newtonIterations = std::max(out.newtonIterations, 0L) + iterations;
    out.rhsEvaluations += rhs + rhsForJacobian;
    out.linearSolverSetups = std::max(out.linearSolverSetups, 0L) + setups;
    out.jacobianEvaluations = std::max(out.jacobianEvaluations, 0L) + jacobians;
    out.errorTestFailures += errorFails;
    out.convergenceFailures += solveFails;
    out.projections += projections;
    out.rootEvaluations = std::max(out.rootEvaluations, 0L) + roots;
}

IntegrationStatistics CvodeSolver::getStatistics() const {
    IntegrationStatistics all = totals_;
    addCurrentCountsTo(all);
    return all;
}

}  // namespace graspsim::integration
