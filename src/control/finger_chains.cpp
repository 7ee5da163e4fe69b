#include "finger_chains.h"

#include "graspsim/error.h"

#include <algorithm>
#include <limits>
#include <memory>

namespace graspsim::control {

namespace {

// The body's mobilizer transform X_FM for coordinate q: a pin turns about F's z, a slider moves
// along F's x (as system/body_mobilizer.cpp builds them), a weld is fixed.
template <class KindT>
SimTK::Transform findX_FM(KindT kind, double q) {
    if (kind == KindT::Pin) return SimTK::Transform(SimTK::Rotation(q, SimTK::ZAxis));
    if (kind == KindT::Slider) return SimTK::Transform(SimTK::Vec3(q, 0, 0));
    return SimTK::Transform();
}

}  // namespace

FingerChains::FingerChains(const system::MultibodyModel& model, const std::vector<std::string>& endEffectors,
                           const std::vector<std::string>& movingJoints)
    : model_(model) {
    const model::ModelDescription& d = model.getDescription();
    const double inf = std::numeric_limits<double>::infinity();
    for (const std::string& joint : movingJoints) {
        const model::Joint* j = d.findJoint(joint);
        if (!j || j->type == model::Joint::Type::Fixed) throw InputError("IK: no movable joint named '" + joint + "'");
        movingBodies_.push_back(model.getMobilizedBody(j->child).getMobilizedBodyIndex());
        joints_.push_back(j->hasLimits() ? MovingJoint{j->lower, j->upper} : MovingJoint{-inf, inf});
    }
    for (const std::string& name : endEffectors) {
        const model::EndEffector* e = d.findEndEffector(name);
        if (!e) throw InputError("IK: no end-effector named '" + name + "'");
        chains_.push_back(makeChain(model.getMobilizedBody(e->body), SimTK::Vec3(e->p_BE[0], e->p_BE[1], e->p_BE[2]), name));
    }
}

// The path from the end-effector's body inward, cut at its innermost moving joint: the links
// further in only carry the chain's base, whose pose capture() reads from the state.
FingerChains::Chain FingerChains::makeChain(const SimTK::MobilizedBody& body, const SimTK::Vec3& p_BE,
                                            const std::string& name) const {
    Chain chain;
    chain.p_BE = p_BE;
    std::vector<Link> path;
    std::size_t innermostMoving = 0;
    for (const SimTK::MobilizedBody* b = &body; !b->isGround(); b = &b->getParentMobilizedBody()) {
        Link link;
        link.body = b->getMobilizedBodyIndex();
        const auto it = std::find(movingBodies_.begin(), movingBodies_.end(), link.body);
        if (it != movingBodies_.end()) {
            link.moving = static_cast<int>(it - movingBodies_.begin());
            innermostMoving = path.size() + 1;
        }
        path.push_back(link);
    }
    path.resize(innermostMoving);
    std::reverse(path.begin(), path.end());
    const SimTK::SimbodyMatterSubsystem& matter = model_.getMatter();
    chain.base = path.empty() ? body.getMobilizedBodyIndex()
                              : matter.getMobilizedBody(path.front().body).getParentMobilizedBody().getMobilizedBodyIndex();
    for (Link& link : path) {
        const SimTK::MobilizedBody& mobod = matter.getMobilizedBody(link.body);
        if (SimTK::MobilizedBody::Pin::isInstanceOf(mobod)) link.kind = Kind::Pin;
        else if (SimTK::MobilizedBody::Slider::isInstanceOf(mobod)) link.kind = Kind::Slider;
        else if (SimTK::MobilizedBody::Weld::isInstanceOf(mobod)) link.kind = Kind::Weld;
        else throw Error("IK: the mobilizer of body " + std::to_string(link.body) + " on the path of '" + name +
                         "' is not a pin, slider or weld");
        link.X_PF = mobod.getDefaultInboardFrame();
        link.X_MB = ~mobod.getDefaultOutboardFrame();
    }
    chain.links = std::move(path);
    return chain;
}

void FingerChains::capture(const SimTK::State& state) {
    // The chains' bases come from Simbody's own kinematics; realize a copy only if the caller's
    // state is not that far (an event handler's state always is).
    std::unique_ptr<SimTK::State> realized;
    const SimTK::State* s = &state;
    if (state.getSystemStage() < SimTK::Stage::Position) {
        realized = std::make_unique<SimTK::State>(state);
        model_.getSystem().realize(*realized, SimTK::Stage::Position);
        s = realized.get();
    }
    const SimTK::SimbodyMatterSubsystem& matter = model_.getMatter();
    X_GBase_.assign(chains_.size(), SimTK::Transform());
    heldQ_.assign(chains_.size(), {});
    for (std::size_t c = 0; c < chains_.size(); ++c) {
        X_GBase_[c] = matter.getMobilizedBody(chains_[c].base).getBodyTransform(*s);
        for (const Link& link : chains_[c].links) {
            heldQ_[c].push_back(link.kind == Kind::Weld ? 0.0 : matter.getMobilizedBody(link.body).getOneQ(*s, 0));
        }
    }
    q0_.clear();
    for (SimTK::MobilizedBodyIndex b : movingBodies_) q0_.push_back(matter.getMobilizedBody(b).getOneQ(*s, 0));
}

void FingerChains::calcLocations(const std::vector<double>& q, std::vector<SimTK::Vec3>& p_GE,
                                 std::vector<double>* jacobian) const {
    const int n = getNumJoints();
    p_GE.resize(chains_.size());
    if (jacobian) jacobian->assign(3 * chains_.size() * n, 0.0);
    struct Axis { int joint; Kind kind; SimTK::Transform X_GF; };
    std::vector<Axis> axes;  // the chain's moving joints, with their F frames in ground
    for (std::size_t c = 0; c < chains_.size(); ++c) {
        const Chain& chain = chains_[c];
        SimTK::Transform X_GB = X_GBase_[c];
        axes.clear();
        for (std::size_t k = 0; k < chain.links.size(); ++k) {
            const Link& link = chain.links[k];
            const SimTK::Transform X_GF = X_GB * link.X_PF;
            if (link.moving >= 0) axes.push_back({link.moving, link.kind, X_GF});
            X_GB = X_GF * findX_FM(link.kind, link.moving >= 0 ? q[link.moving] : heldQ_[c][k]) * link.X_MB;
        }
        p_GE[c] = X_GB * chain.p_BE;
        if (!jacobian) continue;
        for (const Axis& a : axes) {
            // A pin turns E about F's z through F's origin; a slider moves it along F's x.
            const SimTK::Vec3 column = a.kind == Kind::Pin ? SimTK::Vec3(a.X_GF.R().z() % (p_GE[c] - a.X_GF.p()))
                                                           : SimTK::Vec3(a.X_GF.R().x());
            for (int i = 0; i < 3; ++i) (*jacobian)[(3 * c + i) * n + a.joint] = column[i];
        }
    }
}

}  // namespace graspsim::control
