#pragma once
// urdfdom's parser without its console output: urdfdom reports every problem through
// console_bridge on stderr; we collect the messages and put them in one exception instead.

#include <urdf_model/model.h>
#include <urdf_world/types.h>

#include <string>

namespace graspsim::model {

/// What urdf::parseURDF made of some text.
struct UrdfdomParse {
    urdf::ModelInterfaceSharedPtr model;  ///< null when urdfdom rejected the text
    std::string errors;                   ///< urdfdom's error messages, joined by "; "

    /// True when urdfdom returned a model and logged no error. Both are needed: urdfdom 3.0.1
    /// ignores parseLink's result, so a link whose <inertial> it could not read (mass="abc")
    /// is logged as an error but kept, with mass 0.
    bool isAccepted() const { return model && errors.empty(); }
};

/// Runs urdf::parseURDF on `xml` with console_bridge's output captured, then restores the
/// output handler that was in place. Calls are serialized because the handler is process-wide.
UrdfdomParse parseWithUrdfdom(const std::string& xml);

}  // namespace graspsim::model
