// The pieces of messcap's QIF document (qif_document.cpp puts them together): the ids every
// element gets before any is written, so that every reference points at an element of the
// document; the features (qif_features.cpp) and the characteristics with their datums
// (qif_characteristics.cpp).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "qif_xml.hpp"
#include "saved_inspection.hpp"

namespace imess::messcap {

struct QifDefinitionIds {
  unsigned definition = 0, nominal = 0, item = 0;
};

// Ids of the plan's side (from the first run) and of the machines.
struct QifIds {
  unsigned next = 1;
  unsigned take() { return next++; }
  unsigned standard = 0;                                    // the tolerancing standard (ISO 1101)
  std::map<std::string, QifDefinitionIds> features;         // by feature name
  std::vector<QifDefinitionIds> characteristics;            // plan order
  std::map<std::string, unsigned> datum_definitions;        // by feature name
  std::map<std::string, unsigned> datum_frames;             // by datum_frame_key()
  std::map<std::string, unsigned> devices;                  // by machine text
};

// Ids of one run's results.
struct QifRunIds {
  unsigned results = 0;
  std::map<std::string, unsigned> feature_measurements;     // by feature name
  std::map<std::string, unsigned> point_sets;               // by feature name, features with points
  std::vector<unsigned> characteristic_measurements;        // plan order
};

const SavedFeature& saved_feature(const SavedInspection& run, const std::string& name);

// Datums: the alignment's three (position's reference frame) and each orientation datum.
std::string datum_frame_key(const std::vector<std::string>& datums);
std::vector<std::vector<std::string>> datum_frames(const SavedInspection& plan);
// The frame a characteristic refers to (empty: none).
std::vector<std::string> characteristic_datums(const SavedInspection& plan, const SavedCharacteristic& c);

void assign_feature_ids(const SavedInspection& plan, QifIds& ids);
void assign_characteristic_ids(const SavedInspection& plan, QifIds& ids);
QifRunIds assign_run_ids(const SavedInspection& run, QifIds& ids);

void write_datums(XmlWriter& w, const SavedInspection& plan, const QifIds& ids);
void write_features(XmlWriter& w, const SavedInspection& plan, const QifIds& ids);
void write_characteristics(XmlWriter& w, const SavedInspection& plan, const QifIds& ids);
// `device`: the run's machine's MeasurementDevice id, 0 for none.
void write_measured_features(XmlWriter& w, const SavedInspection& run, const QifIds& ids, const QifRunIds& run_ids,
                             unsigned device);
void write_measured_point_sets(XmlWriter& w, const SavedInspection& run, const QifRunIds& run_ids);
void write_measured_characteristics(XmlWriter& w, const SavedInspection& run, const QifIds& ids,
                                    const QifRunIds& run_ids, unsigned device);

}  // namespace imess::messcap
