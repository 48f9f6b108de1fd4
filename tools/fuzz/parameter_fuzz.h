// Fuzzing a node's parameter reading without a ROS master: every node reads its private namespace
// through spott_ros::ParameterReader, which takes the XmlRpc tree that ros::NodeHandle::getParam
// gives. A parameter fuzzer builds that tree from the fuzzer's bytes over the node's config file
// (its keys, sections and words, plus made-up ones), runs the node's real reading and validation,
// and checks what a node that starts would hold:
//
//   extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
//     static const auto vocabulary =
//         spott_fuzz::LoadVocabulary(CONFIG_FILE, {{"world_file", "/tmp/world.yaml"}});
//     FuzzedDataProvider in(data, size);
//     spott_ros::ParameterReader r(spott_fuzz::BuildParameters(in, vocabulary));
//     NodeParameters p;
//     ReadParameters(r, p);
//     if (!r.Finish().empty()) return 0;              // the node stops: nothing to check
//     spott_fuzz::ExpectIn("cycle_rate_hz", p.cycle_rate_hz, "(0, 1000]");   // documented range
//     spott_fuzz::ExpectRosDuration("1 / cycle_rate_hz", 1.0 / p.cycle_rate_hz);  // its timer
//     return 0;
//   }
//
// A failed expectation prints the parameter tree of the input (as YAML) and aborts, so that
// libFuzzer keeps the input as a crash; the tree is what a regression test sets.
#pragma once

#include <fuzzer/FuzzedDataProvider.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include <string>
#include <utility>
#include <vector>

namespace spott_fuzz {

/// A node's config file (config/<node>.yaml) as the parameter server holds it, and what the
/// fuzzer draws keys and strings from.
struct ParameterVocabulary {
  XmlRpc::XmlRpcValue config;         ///< The file's tree (a struct).
  std::vector<std::string> keys;      ///< Every leaf's path ("window/resolution_m").
  std::vector<std::string> sections;  ///< Every section's path ("window").
  std::vector<std::string> words;     ///< Every string value of the file, and the extra words.
};

/// Loads `yaml_file` (scalars typed as rosparam types them: integer, number, true/false, else a
/// string). `launch`: what the launch files set beside the file (world_file, program_file: the
/// string keys a node requires), added to the tree; `extra_keys`: other keys the node reads that
/// the file leaves out; `extra_words`: strings worth trying (the accepted values of an enum).
/// Aborts when the file cannot be read: a fuzzer without its vocabulary is no fuzzer.
ParameterVocabulary LoadVocabulary(
    const std::string& yaml_file,
    const std::vector<std::pair<std::string, std::string>>& launch = {},
    const std::vector<std::string>& extra_keys = {},
    const std::vector<std::string>& extra_words = {});

/// The node's private namespace built from the fuzzer's bytes: the config file's tree (or
/// nothing, or a namespace that is not a section), then edits while bytes last (at most 48): a
/// key, known or made up (below a leaf, with an empty or a '/' name), set to a value of any
/// XmlRpc type (NaN, infinities, huge, tiny and negative numbers, integers where numbers are
/// expected and the converse, empty and long strings, nested sections and lists, dates, binary,
/// invalid), removed, or its number nudged (scaled, negated, moved to the next double).
XmlRpc::XmlRpcValue BuildParameters(FuzzedDataProvider& in, const ParameterVocabulary& vocabulary);

/// The tree as YAML text (for the report of a finding and for regression tests).
std::string ToYaml(const XmlRpc::XmlRpcValue& value);

/// A finding unless `ok`: prints `what` and the last built tree, then aborts.
void Expect(bool ok, const std::string& what);
/// `value` finite and within `range`, in interval notation: "(0, 1000]", "[0, inf)",
/// "[0, pi/2)"; bounds are numbers, "inf", "pi", "pi/2" or "2pi".
void ExpectIn(const std::string& name, double value, const std::string& range);
void ExpectFinite(const std::string& name, double value);
/// A period or timeout that the node turns into a ros::Duration (a timer, a wait): it must make
/// one (ros::Duration throws beyond 2^31 s and is undefined for non-finite seconds).
void ExpectRosDuration(const std::string& name, double seconds);

}  // namespace spott_fuzz
