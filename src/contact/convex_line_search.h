#pragma once
// Minimizing a convex function of one parameter t in [0, 1]: the signed distance of a convex
// solid along a segment (capsule axis, box edge), or the distance from a point on one segment
// to another segment. Private to the contact layer.

namespace graspsim::contact {

/// Where a convex function of t in [0, 1] is (within valueTolerance of) its minimum: the
/// interval [lower, upper] of t.
struct ArgminInterval {
    double lower = 0;
    double upper = 0;
    double middle() const { return 0.5 * (lower + upper); }
};

/// Width (in t) to which the minimizer and the ends of the flat interval are located.
constexpr double kLineSearchTolerance = 1e-12;

/// The interval of t in [0, 1] where convex f is within valueTolerance of its minimum.
///
/// Golden-section search brackets a minimizer (for convex f, f(x1) <= f(x2) means a minimizer
/// lies in [a, x2], ties included, so the bracket never loses it); bisection then finds the
/// ends of the level set {f <= min + valueTolerance}, which is an interval because f is convex.
/// When f is flat over an interval (a segment parallel to a face) that interval is returned
/// whole, so the caller can put the contact at its middle instead of wherever the search
/// happened to stop. About 100 evaluations of f (140 when the minimum is flat).
template <class Function>
ArgminInterval findConvexArgminInterval(const Function& f, double valueTolerance) {
    constexpr double kInvPhi = 0.61803398874989485;  // 1 / golden ratio
    double a = 0, b = 1;
    double x1 = b - kInvPhi * (b - a), x2 = a + kInvPhi * (b - a);
    double f1 = f(x1), f2 = f(x2);
    while (b - a > kLineSearchTolerance) {
        if (f1 <= f2) {
            b = x2, x2 = x1, f2 = f1;
            x1 = b - kInvPhi * (b - a), f1 = f(x1);
        } else {
            a = x1, x1 = x2, f1 = f2;
            x2 = a + kInvPhi * (b - a), f2 = f(x2);
        }
    }
    // The bracket's middle, unless an end is lower (a minimum at t = 0 or 1 is approached but
    // never evaluated by the bracket).
    double tBest = 0.5 * (a + b), fBest = f(tBest);
    const double f0 = f(0.0), fEnd = f(1.0);
    if (f0 < fBest) tBest = 0, fBest = f0;
    if (fEnd < fBest) tBest = 1, fBest = fEnd;
    const double threshold = fBest + valueTolerance;

    // Ends of the level set by bisection. Most minima are sharp or round rather than flat, so
    // first try a short bracket next to tBest; that halves the cost of the common case.
    constexpr double kShortBracket = 1e-6;
    ArgminInterval result{tBest, tBest};
    if (f0 <= threshold) {
        result.lower = 0;
    } else {  // invariant: f(lo) > threshold >= f(hi)
        double lo = 0, hi = tBest;
        const double near = tBest - kShortBracket;
        if (near > 0) (f(near) > threshold ? lo : hi) = near;
        while (hi - lo > kLineSearchTolerance) {
            const double mid = 0.5 * (lo + hi);
            (f(mid) <= threshold ? hi : lo) = mid;
        }
        result.lower = hi;
    }
    if (fEnd <= threshold) {
        result.upper = 1;
    } else {  // invariant: f(lo) <= threshold < f(hi)
        double lo = tBest, hi = 1;
        const double near = tBest + kShortBracket;
        if (near < 1) (f(near) > threshold ? hi : lo) = near;
        while (hi - lo > kLineSearchTolerance) {
            const double mid = 0.5 * (lo + hi);
            (f(mid) <= threshold ? lo : hi) = mid;
        }
        result.upper = lo;
    }
    return result;
}

}  // namespace graspsim::contact
