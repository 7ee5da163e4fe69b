#include "model_command.h"

#include "number_option.h"
#include "output_file.h"

#include "graspsim/anthropometry/sex.h"
#include "graspsim/anthropometry/subject.h"
#include "graspsim/error.h"
#include "graspsim/io/atomic_file.h"
#include "graspsim/model/body_model.h"
#include "graspsim/model/object_model.h"
#include "graspsim/model/urdf_export.h"
#include "graspsim/model/urdf_import.h"
#include "graspsim/opensim/osim_model.h"
#include "graspsim/system/multibody_model.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace graspsim::cli {

struct ModelCommand::Options {
    std::string sex = "male";
    std::string mass, stature, preset = "none", body = "arm", output;
    std::string fingerStiffness, fingerDamping;
    std::string infoFile;
    std::string objectName, objectOutput;
    bool json = false;
};

ModelCommand::ModelCommand(CLI::App& app) : options_(std::make_shared<Options>()) {
    CLI::App* model = app.add_subcommand("model", "Build anthropometric models and inspect URDF files");
    model_ = model;
    model->require_subcommand(0, 1);  // none given: run() says which exist; unknown ones: CLI11 names them
    Options& o = *options_;

    build_ = model->add_subcommand("build", "Build a de Leva arm/hand (or humanoid) model and write it as URDF");
    build_->add_option("--sex", o.sex, "male or female (default male)");
    build_->add_option("--mass", o.mass, "body mass in kg, 20 to 250 (default: de Leva reference subject)");
    build_->add_option("--stature", o.stature, "stature in m, 1.0 to 2.5 (default: de Leva reference subject)");
    build_->add_option("--preset", o.preset, "thesis: finger segments 20 g, palm 250 g, arm 5.45 kg");
    build_->add_option("--body", o.body, "arm (right arm + hand, 27 DOF; default) or humanoid");
    build_->add_option("--finger-stiffness", o.fingerStiffness, "finger joint stiffness in N m/rad (default 0.25)");
    build_->add_option("--finger-damping", o.fingerDamping, "finger joint damping in N m s/rad (default 0.05)");
    build_->add_option("-o,--output", o.output, "file to write: URDF, or an OpenSim 4 model when it ends in .osim")->required();

    object_ = model->add_subcommand("object", "Write one of the thesis's objects (ball 200 g, phone 100 g) as URDF");
    object_->add_option("name", o.objectName, "ball or phone")->required();
    object_->add_option("-o,--output", o.objectOutput, "file to write: URDF, or an OpenSim 4 model when it ends in .osim")->required();

    info_ = model->add_subcommand("info", "Summarize a URDF model: bodies, DOF, total and per-segment mass");
    info_->add_option("file", o.infoFile, "URDF file")->required();
    info_->add_flag("--json", o.json, "print JSON instead of text");
}

namespace {

model::BuildOptions parseBuildOptions(const std::string& sex, const std::string& mass, const std::string& stature,
                                      const std::string& preset, const std::string& body) {
    model::BuildOptions options;
    options.subject = anthropometry::getReferenceSubject(anthropometry::parseSex(sex, "--sex"));
    if (!mass.empty()) {
        options.subject.mass = parseNumber(mass, "--mass", "body mass must be a number in [20, 250] kg");
    }
    if (!stature.empty()) {
        options.subject.stature = parseNumber(stature, "--stature", "stature must be a number in [1.0, 2.5] m");
    }
    anthropometry::validateBodyMass(options.subject.mass, "--mass");
    anthropometry::validateStature(options.subject.stature, "--stature");
    options.preset = model::parsePreset(preset, "--preset");
    options.body = model::parseBodyKind(body, "--body");
    // The thesis's arm has its own masses: on the arm body no subject mass scales anything.
    if (options.preset == model::Preset::Thesis && options.body == model::BodyKind::Arm && !mass.empty()) {
        throw InputError("--mass: value " + mass + " is not accepted with --preset thesis on the arm body, whose masses are the "
                         "thesis's (arm 5.45 kg); leave out --mass or --preset");
    }
    return options;
}

std::string formatMass(double kg) {
    char text[32];
    std::snprintf(text, sizeof text, "%g kg", kg);
    return text;
}

void parseFingerOptions(const std::string& stiffness, const std::string& damping, model::BuildOptions& options) {
    if (!stiffness.empty()) {
        options.fingerStiffness = parseNumber(stiffness, "--finger-stiffness", "a number >= 0 N m/rad");
    }
    if (!damping.empty()) {
        options.fingerDamping = parseNumber(damping, "--finger-damping", "a number >= 0 N m s/rad");
    }
}

// The file's format follows its extension: .osim (any case) is an OpenSim 4 model, anything else URDF.
std::string formatModelFile(const model::ModelDescription& description, const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    const bool isOsim = extension == ".osim";
    return isOsim ? opensim::writeOsim(description) : model::writeUrdf(description);
}

// Builds the Simbody system too, so `info` vouches that the file simulates, not just parses.
int countSimbodyDofs(const model::ModelDescription& description) {
    system::MultibodyModel multibody(description);
    multibody.realizeTopology();
    return multibody.getSystem().getMatterSubsystem().getNumMobilities();
}

nlohmann::ordered_json makeInfoJson(const model::ModelDescription& m, const std::string& file, int simbodyDofs) {
    nlohmann::ordered_json segments = nlohmann::ordered_json::object();
    for (const auto& [segment, mass] : m.calcSegmentMasses()) {
        if (mass > 0) segments[segment] = mass;  // massless anchors and joint-chain links are not segments
    }
    int virtualBodies = 0;
    for (const auto& b : m.bodies) virtualBodies += b.isVirtual() ? 1 : 0;
    nlohmann::ordered_json endEffectors = nlohmann::ordered_json::array();
    for (const auto& e : m.endEffectors) endEffectors.push_back(e.name);
    return {{"file", file},
            {"name", m.name},
            {"bodies", static_cast<int>(m.bodies.size())},
            {"massive_bodies", static_cast<int>(m.bodies.size()) - virtualBodies},
            {"virtual_bodies", virtualBodies},
            {"joints", static_cast<int>(m.joints.size())},
            {"dof", m.getDofCount()},
            {"simbody_mobilities", simbodyDofs},
            {"total_mass_kg", m.calcTotalMass()},
            {"segment_mass_kg", segments},
            {"end_effectors", endEffectors}};
}

void printInfoText(const nlohmann::ordered_json& info) {
    std::cout << "model " << info["name"].get<std::string>() << " (" << info["file"].get<std::string>() << ")\n"
              << "  bodies: " << info["bodies"] << " (" << info["massive_bodies"] << " with mass, "
              << info["virtual_bodies"] << " massless joint-chain links)\n"
              << "  DOF: " << info["dof"] << " (Simbody mobilities: " << info["simbody_mobilities"] << ")\n"
              << std::fixed << std::setprecision(4)
              << "  total mass: " << info["total_mass_kg"].get<double>() << " kg\n"
              << "  mass per segment (kg):\n";
    for (const auto& [segment, mass] : info["segment_mass_kg"].items()) {
        std::cout << "    " << std::left << std::setw(16) << segment << std::right << mass.get<double>() << "\n";
    }
    std::cout << "  end effectors:";
    for (const auto& e : info["end_effectors"]) std::cout << " " << e.get<std::string>();
    std::cout << "\n";
}

}  // namespace

bool ModelCommand::parsed() const { return model_->parsed(); }

void ModelCommand::checkOptions() const {
    const Options& o = *options_;
    if (build_->parsed()) {
        model::BuildOptions options = parseBuildOptions(o.sex, o.mass, o.stature, o.preset, o.body);
        parseFingerOptions(o.fingerStiffness, o.fingerDamping, options);
        checkOutputFile(o.output, "--output");
    }
    if (object_->parsed()) {
        model::buildObjectModel(o.objectName, "object name");
        checkOutputFile(o.objectOutput, "--output");
    }
}

int ModelCommand::run() const {
    const Options& o = *options_;
    if (!build_->parsed() && !object_->parsed() && !info_->parsed()) {
        throw InputError("model: a subcommand is required: build, object or info (see graspsim model --help)");
    }
    checkOptions();
    if (build_->parsed()) {
        model::BuildOptions options = parseBuildOptions(o.sex, o.mass, o.stature, o.preset, o.body);
        parseFingerOptions(o.fingerStiffness, o.fingerDamping, options);
        const model::ModelDescription description = model::buildBodyModel(options);
        io::writeFileAtomically(o.output, formatModelFile(description, o.output));
        std::cout << "wrote " << o.output << ": " << description.bodies.size() << " bodies, "
                  << description.getDofCount() << " DOF, " << std::fixed << std::setprecision(4)
                  << description.calcTotalMass() << " kg"
                  << (options.preset == model::Preset::Thesis && options.body == model::BodyKind::Humanoid
                          ? " (the thesis's 5.45 kg arms on de Leva's other segments of the " + formatMass(options.subject.mass) + " subject)"
                          : "")
                  << "\n";
        return 0;
    }
    if (object_->parsed()) {
        const model::ModelDescription description = model::buildObjectModel(o.objectName, "object name");
        io::writeFileAtomically(o.objectOutput, formatModelFile(description, o.objectOutput));
        std::cout << "wrote " << o.objectOutput << ": " << o.objectName << ", " << description.calcTotalMass()
                  << " kg\n";
        return 0;
    }
    const model::ModelDescription description = model::importUrdf(o.infoFile);
    const nlohmann::ordered_json info = makeInfoJson(description, o.infoFile, countSimbodyDofs(description));
    if (o.json) {
        std::cout << info.dump(2) << "\n";
    } else {
        printInfoText(info);
    }
    return 0;
}

}  // namespace graspsim::cli
