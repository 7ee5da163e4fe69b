// Builds the arm and hand of one subject from de Leva's anthropometric tables and writes the model
// as URDF and as an OpenSim 4 model.
//
//   build_and_export_model [OUTPUT_STEM]   writes OUTPUT_STEM.urdf and OUTPUT_STEM.osim (default: arm)

#include <graspsim/anthropometry/subject.h>
#include <graspsim/error.h>
#include <graspsim/io/atomic_file.h>
#include <graspsim/model/body_model.h>
#include <graspsim/model/urdf_export.h>
#include <graspsim/opensim/osim_model.h>

#include <iostream>
#include <string>

int main(int argc, char** argv) {
    const std::string stem = argc > 1 ? argv[1] : "arm";
    try {
        // The subject: start from de Leva's female reference subject and give her own mass and
        // stature (kg, m). Segment lengths, masses and inertias scale from the tables.
        graspsim::model::BuildOptions options;
        options.subject = graspsim::anthropometry::getReferenceSubject(graspsim::anthropometry::Sex::Female);
        options.subject.mass = 58.0;
        options.subject.stature = 1.64;
        const graspsim::model::ModelDescription model = graspsim::model::buildBodyModel(options);

        // One description, two file formats. writeFileAtomically never leaves half a file.
        graspsim::io::writeFileAtomically(stem + ".urdf", graspsim::model::writeUrdf(model));
        graspsim::io::writeFileAtomically(stem + ".osim", graspsim::opensim::writeOsim(model));
        std::cout << "wrote " << stem << ".urdf and " << stem << ".osim: " << model.bodies.size() << " bodies, "
                  << model.getDofCount() << " DOF, " << model.calcTotalMass() << " kg\n";
    } catch (const graspsim::Error& e) {  // bad input or an unwritable path: one line, no file
        std::cerr << e.what() << "\n";
        return 2;
    }
    return 0;
}
