#pragma once
/// @file
/// The replay viewer's page: one self-contained HTML file (three.js and OrbitControls from Debian's
/// libjs-three inlined, the run's data embedded as JSON) that opens from disk with no server.
///
/// The page shows the arm, hand and object with their model shapes, posed at every recorded sample
/// (the poses are computed here, by forward kinematics of model.urdf at the recorded joint angles,
/// so the page needs no kinematics); play / pause, speed, a time bar to scrub with the
/// approximation's engaged intervals marked on it; the contact forces on the object as arrows
/// (with a scale legend); each finger's state (free, in contact with its force, or locked to the
/// palm while the merged approximation is engaged); the constraint's frame, its per-axis
/// reaction against its limits while engaged; and the object's path.
///
/// The page reports its own state for tests: once drawn, document.title reads
/// "graspsim replay: ready" and the element with id "replay-state" holds JSON {frames, bodies, drawn,
/// time, webgl, errors} (errors counts console errors and uncaught exceptions). Opened as
/// replay.html?t=SECONDS it shows that instant, still, for pictures (still_picture.h).

#include "graspsim/viewer/result_reader.h"

#include <string>

namespace graspsim::viewer {

/// The JSON data the page replays (bodies with shapes, per-sample poses, contacts, events,
/// constraint samples).
std::string formatReplayJson(const ResultRecord& record);

/// The whole page's HTML.
std::string makeReplayPage(const ResultRecord& record);

/// Reads the result folder, writes `folder`/replay.html (whole, or not at all) and returns its path.
/// @throws graspsim::InputError as readResultFolder, or when the page cannot be written.
std::string writeReplayPage(const std::string& folder);

}  // namespace graspsim::viewer
