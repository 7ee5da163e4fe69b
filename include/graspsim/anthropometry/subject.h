#pragma once
/// @file
/// The person being modelled: sex, body mass and stature, with the accepted ranges.

#include <graspsim/anthropometry/sex.h>

#include <string>

namespace graspsim::anthropometry {

/// Body measurements that scale the de Leva segment table to one person.
/// The defaults are de Leva's (1996) male reference subject; a test pins them to
/// anthropometry/de_leva_1996_reference_subjects.csv.
struct Subject {
    Sex sex = Sex::Male;   ///< selects the female or male column of the tables
    double mass = 73.0;    ///< body mass (kg)
    double stature = 1.741;  ///< standing height (m)
};

/// Smallest and largest accepted body mass (kg) and stature (m).
constexpr double kMinBodyMass = 20.0;
constexpr double kMaxBodyMass = 250.0;
constexpr double kMinStature = 1.0;
constexpr double kMaxStature = 2.5;

/// Throws InputError unless `mass` (kg) is finite and in [20, 250]. `source` names the value,
/// e.g. a flag: "--mass: value nan is not accepted; body mass must be a finite number in
/// [20, 250] kg".
void validateBodyMass(double mass, const std::string& source);

/// Throws InputError unless `stature` (m) is finite and in [1, 2.5]; message as for mass.
void validateStature(double stature, const std::string& source);

/// Validates both fields; `source` names where the subject came from, and the message names
/// the field: "<source>: field 'mass' value nan is not accepted; body mass must be ...".
void validateSubject(const Subject& subject, const std::string& source);

/// de Leva's (1996) reference subject of `sex` (female 61.9 kg, 1.735 m; male 73.0 kg,
/// 1.741 m), read from the embedded anthropometry/de_leva_1996_reference_subjects.csv.
Subject getReferenceSubject(Sex sex);

}  // namespace graspsim::anthropometry
