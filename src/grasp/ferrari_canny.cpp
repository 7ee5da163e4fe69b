#include "graspsim/grasp/ferrari_canny.h"

#include "graspsim/error.h"

#include <Eigen/SVD>

extern "C" {
#include <libqhull_r/libqhull_r.h>
}

#include <algorithm>
#include <cstdio>  // open_memstream (POSIX)
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

namespace graspsim::grasp {

namespace {

// Relative size of the 6th singular value of the centred columns below which the hull is taken
// as flat. Real grasps sit far above it (torque rows are ~ mu * size / L relative to the force
// rows); exactly flat sets (one contact, antipodal pairs) sit at round-off, ~1e-16.
const double kFlatTolerance = 1e-10;

bool isFullDimensional(const Eigen::MatrixXd& G) {
    if (G.cols() < 7) return false;  // a 6-simplex needs 7 vertices
    const Eigen::MatrixXd centred = G.colwise() - G.rowwise().mean();
    const Eigen::VectorXd s = Eigen::JacobiSVD<Eigen::MatrixXd>(centred).singularValues();
    return s(0) > 0 && s(5) > kFlatTolerance * s(0);
}

// The outcome of one qhull run: its exit code, its message, and the distance from the origin to
// the nearest facet hyperplane (negative if the origin is outside some facet).
struct HullResult {
    int exitCode = 0;
    std::string message;
    double minOriginDistance = std::numeric_limits<double>::infinity();
};

// qhull writes a facet's hyperplane as normal . x + offset = 0 with the unit normal pointing out
// of the hull, so the signed distance from the origin (inside positive) is -offset.
HullResult runQhull(std::vector<double> points, int numPoints, const char* options) {
    HullResult result;
    // qhull reports through a FILE*; an in-memory stream keeps its messages off stderr and lets
    // an error carry them.
    char* text = nullptr;
    std::size_t textSize = 0;
    std::FILE* errors = open_memstream(&text, &textSize);
    if (!errors) throw Error("Ferrari-Canny: cannot open a memory stream for qhull's messages");
    qhT qh;
    QHULL_LIB_CHECK
    qh_zero(&qh, errors);
    std::string command = std::string("qhull ") + options;
    result.exitCode =
        qh_new_qhull(&qh, 6, numPoints, points.data(), False, command.data(), nullptr, errors);
    if (result.exitCode == qh_ERRnone) {
        for (facetT* facet = qh.facet_list; facet && facet->next; facet = facet->next)
            result.minOriginDistance = std::min(result.minOriginDistance, -facet->offset);
    }
    qh_freeqhull(&qh, !qh_ALL);
    int curlong = 0, totlong = 0;
    qh_memfreeshort(&qh, &curlong, &totlong);
    std::fclose(errors);  // flushes into `text`
    if (result.exitCode != qh_ERRnone) result.message.assign(text, textSize);
    std::free(text);
    return result;
}

std::string firstLine(const std::string& text) {
    const std::size_t start = text.find_first_not_of(" \n");
    if (start == std::string::npos) return "(no message)";
    return text.substr(start, text.find('\n', start) - start);
}

}  // namespace

double calcFerrariCanny(const Eigen::MatrixXd& G) {
    if (G.rows() != 6)
        throw InputError("Ferrari-Canny: the grasp matrix must have 6 rows (got " +
                         std::to_string(G.rows()) + ")");
    if (!G.allFinite()) throw InputError("Ferrari-Canny: the grasp matrix has a non-finite entry");
    if (!isFullDimensional(G)) return 0;

    const std::vector<double> points(G.data(), G.data() + G.size());  // column j = point j
    const int n = static_cast<int>(G.cols());
    HullResult hull = runQhull(points, n, "");
    // Nearly degenerate wrench sets (many coplanar basis wrenches) can trip qhull's exact-merge
    // precision checks; joggling the input by ~1e-11 relative is qhull's own remedy and moves
    // epsilon by about that much.
    if (hull.exitCode != qh_ERRnone && hull.exitCode != qh_ERRsingular)
        hull = runQhull(points, n, "QJ");
    if (hull.exitCode == qh_ERRsingular) return 0;  // flat after all: no 6-D ball fits
    if (hull.exitCode != qh_ERRnone)
        throw NumericalError("Ferrari-Canny: qhull failed (exit code " +
                             std::to_string(hull.exitCode) + "): " + firstLine(hull.message));
    return std::max(0.0, hull.minOriginDistance);
}

}  // namespace graspsim::grasp
