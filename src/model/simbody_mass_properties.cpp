#include "simbody_mass_properties.h"

#include "graspsim/error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

namespace graspsim::model {

namespace {

using Matrix3 = std::array<std::array<double, 3>, 3>;

constexpr double kEps = std::numeric_limits<double>::epsilon();  // SimTK::Eps
constexpr const char* kAxes[3] = {"x", "y", "z"};

// Enough digits to show a violation of a few parts in 1e7 (100.00001 against 100).
std::string formatValue(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", value);
    return text;
}

// Three digits: excesses, slops and limits.
std::string formatShort(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

std::string moment(int i) { return std::string("i") + kAxes[i] + kAxes[i]; }

std::string product(int i, int j) { return std::string("i") + kAxes[std::min(i, j)] + kAxes[std::max(i, j)]; }

[[noreturn]] void fail(const std::string& source, const Body& body, const std::string& field, const std::string& value,
                       const std::string& accepted) {
    throw InputError(source + ": link '" + body.name + "' " + field + " = " + value + " is not accepted; " + accepted);
}

// The first of Simbody's rules the recovered central inertia I breaks, as "izz exceeds ixx + iyy
// by 1e-05 kg m^2", or "" when it keeps them all.
std::string findBrokenRule(const Matrix3& I, double slop) {
    for (int i = 0; i < 3; ++i) {
        if (I[i][i] < 0) return moment(i) + " is " + formatValue(I[i][i]) + " kg m^2, below 0";
    }
    for (int k = 0; k < 3; ++k) {
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        const double excess = I[k][k] - (I[i][i] + I[j][j]);
        if (excess > slop) {
            return moment(k) + " exceeds " + moment(std::min(i, j)) + " + " + moment(std::max(i, j)) + " by " +
                   formatShort(excess) + " kg m^2";
        }
    }
    for (int k = 0; k < 3; ++k) {
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        const double excess = std::abs(2 * I[i][j]) - I[k][k];
        if (excess > slop) return "|2 " + product(i, j) + "| exceeds " + moment(k) + " by " + formatShort(excess) + " kg m^2";
    }
    return "";
}

}  // namespace

void checkMassPropertiesForSimbody(const std::string& source, const Body& body) {
    if (body.isVirtual()) return;
    const Inertia& given = body.inertia;
    const Vec3& p = body.p_BCm;
    const double m = body.mass;
    const double p2 = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
    // What Simbody will hold (the inertia about the body origin, I_Bo = I_Bcm + m (|p|^2 1 - p p^T))
    // and the central inertia it recovers from that, rounded as Simbody rounds it.
    const Matrix3 I_Bcm_given{{{given.xx, given.xy, given.xz}, {given.xy, given.yy, given.yz}, {given.xz, given.yz, given.zz}}};
    Matrix3 I_Bcm;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            const double pointMass = m * ((i == j ? p2 : 0.0) - p[i] * p[j]);
            I_Bcm[i][j] = (I_Bcm_given[i][j] + pointMass) - pointMass;
        }
    }
    // Simbody's slop for its inertia checks is sqrt(eps) max(trace, 1); we keep half of it as a
    // margin, and ask the rounding of the shift (a few eps m|p|^2) to stay below the other half,
    // so that our arithmetic and Simbody's cannot land on different sides of its bound.
    const double slop = 0.5 * std::sqrt(kEps) * std::max(I_Bcm[0][0] + I_Bcm[1][1] + I_Bcm[2][2], 1.0);
    const double shift = m * p2;
    if (!(8 * kEps * shift < slop)) {
        fail(source, body, "centre of mass",
             "(" + formatValue(p[0]) + ", " + formatValue(p[1]) + ", " + formatValue(p[2]) + ") m",
             "with mass " + formatValue(m) + " kg, m |p|^2 = " + formatShort(shift) +
                 " kg m^2 swamps the central inertia (trace " + formatShort(given.xx + given.yy + given.zz) +
                 " kg m^2) when Simbody shifts it to the link origin; accepted: m |p|^2 below " +
                 formatShort(slop / (8 * kEps)) + " kg m^2 (put the link origin nearer the mass centre)");
    }
    const std::string broken = findBrokenRule(I_Bcm, slop);
    if (broken.empty()) return;
    fail(source, body, "inertia",
         "[" + formatValue(given.xx) + " " + formatValue(given.yy) + " " + formatValue(given.zz) + " " +
             formatValue(given.xy) + " " + formatValue(given.xz) + " " + formatValue(given.yz) + "] kg m^2",
         "Simbody accepts a central inertia whose moments are >= 0, each at most the sum of the other two and at "
         "least 2 |the product of the other two axes| (ixx >= 2 |iyz|), all within " + formatShort(slop) + " kg m^2; here " + broken);
}

}  // namespace graspsim::model
