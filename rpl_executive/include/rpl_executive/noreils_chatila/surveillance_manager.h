// The surveillance manager (SM) and its sensor surveillance managers (SSMs), section 4.1.
//
// The SM receives monitors from the executive, decomposes each left-hand side into parts, one
// per sensor (the largest sub-formulas whose conditions all belong to one sensor), and sends
// each part to that sensor's SSM (US-SSM for the ultrasonic belt, POSE-SSM for odometry /
// localization, LASER-SSM, BATTERY-SSM). An SSM evaluates its parts on each new datum of its
// sensor: all conditions of one part are evaluated on the same datum, so they trigger
// simultaneously or not at all (section 4.1.2). The SM then evaluates the monitor's formula
// across sensors on the latest part values (a part older than part_validity_s is unknown;
// three-valued logic, so a monitor fires only when its formula is surely true), and fires at
// once: it runs the reflex action on the modules (Fig. 5, 6-1) and informs the executive
// (6-2). A fired monitor stops being evaluated; the executive destroys it.
//
// Firings caused by one datum are simultaneous; they are handled in this priority order
// (section 4.1.3): O-surveillances before P-surveillances (the robot's operation first),
// terminal before non-terminal (stop the motion before anything else), static before
// non-static, then the order in which the monitors are written in the mission, then their
// identifiers. Every reflex runs, in that order; the executive runs the control actions in
// the same order.
//
// Deterministic and single-threaded: time comes with every call; no clock is read.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "rpl_executive/noreils_chatila/conditions.h"
#include "rpl_executive/noreils_chatila/messages.h"
#include "rpl_executive/noreils_chatila/robot_modules.h"
#include "rpl_executive/noreils_chatila/sensor_data.h"
#include "rpl_executive/noreils_chatila/sonar_interpretation.h"

namespace rpl_executive::noreils_chatila {

using MonitorId = int;

struct SurveillanceParameters {
  /// How long a part's value counts in a formula that spans sensors, s, (0, inf).
  double part_validity_s = 0.5;
  /// S_laser-threshold looks at returns within this angle of the robot's heading, (0, pi].
  double laser_front_half_angle_rad = kPi / 2;
  SonarInterpretationParameters sonar;
};
std::vector<std::string> ValidateParameters(const SurveillanceParameters& p);

/// What the executive sends with a monitor (Fig. 5, message 2).
struct MonitorRequest {
  std::string label;  ///< e.g. "MNTR (S_zone IN ZONE109) at mission2.nc:16:5"
  CompiledCondition condition;
  std::vector<OperatorCommand> reflex;  ///< decoded when the monitor is created
  bool o_surveillance = false;
  bool terminal = false;
  bool is_static = false;
  long rank = 0;  ///< where it is written (smaller first) for the priority order
};

struct Firing {
  MonitorId id = 0;
  std::string label;
  bool o_surveillance = false;
  bool terminal = false;
  bool is_static = false;
};

/// The executive's side of message 6-2.
class SurveillanceListener {
 public:
  virtual ~SurveillanceListener() = default;
  virtual void OnMonitorFired(const Firing& firing, double now) = 0;
};

class SurveillanceManager {
 public:
  /// `modules` carries the reflex actions, `log` records the messages (both outlive the SM);
  /// `next_handle` numbers the reflex operators among the executive's.
  SurveillanceManager(const SurveillanceParameters& parameters, const SonarRing& ring,
                      RobotModules* modules, MessageLog* log,
                      std::function<OperatorHandle()> next_handle);

  void set_listener(SurveillanceListener* listener) { listener_ = listener; }

  /// Message 2 -> 3: takes the monitor and returns its identifier (not evaluated yet).
  MonitorId Register(MonitorRequest request, double now);
  /// When an activated monitor is first evaluated.
  enum class Activation {
    kNextDatum,   ///< on its sensors' next data (a new monitor)
    kAtOnce,      ///< now, on the latest data too (a static monitor that becomes active again
                  ///< after a failure "while its conditions are still true", Example 2)
    kAfterFalse,  ///< fires only after its formula has been false once (an O-surveillance
                  ///< re-armed after firing: once per event, not once per datum)
  };
  /// Message 4: sends the parts to the SSMs.
  void Activate(MonitorId id, double now, Activation mode);
  /// Removes a monitor (destroyed after firing, or killed with its action). False if unknown.
  bool Remove(MonitorId id);
  bool IsActive(MonitorId id) const;
  size_t active_count() const;
  /// "<id>: <label>" of every active monitor, by id.
  std::vector<std::string> ActiveLabels() const;

  void OnSonar(const SonarScan& scan, double now);
  void OnPose(const PoseDatum& pose, double now);
  void OnLaser(const LaserScan& scan, double now);
  void OnBattery(const BatteryDatum& battery, double now);

  /// Evaluates a condition once on the sensors' latest data (tests of PRE:, IF and WHILE).
  /// nullopt when a sensor it needs has no datum within part_validity_s. Crossings are events
  /// and are false here.
  std::optional<bool> EvaluateOnLatest(const CompiledCondition& condition, double now);

  /// The lines of the latest sonar scan (computed once per scan, when first needed).
  const std::vector<SonarLine>& latest_lines();
  const SonarRing& ring() const { return ring_; }
  const SurveillanceParameters& parameters() const { return parameters_; }

 private:
  enum class Truth { kFalse, kTrue, kUnknown };
  struct Formula {  // the SM's formula over parts
    CompiledCondition::Op op = CompiledCondition::Op::kAtom;
    int part = -1;  // kAtom: index into Record::parts
    std::vector<Formula> children;
  };
  struct Part {
    SensorKind sensor = SensorKind::kPose;
    CompiledCondition condition;                       // all atoms of `sensor`
    std::vector<std::optional<double>> crossing_side;  // per crossing atom, in DFS order
    bool value = false;
    bool evaluated = false;
    double stamp = 0.0;
  };
  struct Record {
    MonitorId id = 0;
    MonitorRequest request;
    Formula formula;
    std::vector<Part> parts;
    bool active = false;
    bool must_see_false = false;
  };

  Formula Split(const CompiledCondition& c, Record* record);
  static int CountCrossings(const CompiledCondition& c);
  bool EvaluatePart(Part* part, double now, bool latest_only);
  bool EvaluateAtom(const CompiledCondition& c, Part* part, int* crossing, bool latest_only);
  Truth EvaluateFormula(const Formula& f, const Record& r, double now) const;
  Record* Find(MonitorId id);
  const Record* Find(MonitorId id) const;
  void OnDatum(SensorKind sensor, double now);
  void Fire(std::vector<Record*> fired, double now);

  SurveillanceParameters parameters_;
  SonarRing ring_;
  RobotModules* modules_;
  MessageLog* log_;
  std::function<OperatorHandle()> next_handle_;
  SurveillanceListener* listener_ = nullptr;
  MonitorId next_id_ = 1;
  std::vector<Record> records_;  // ordered by id

  // Latest datum of each sensor.
  std::optional<SonarScan> sonar_;
  std::optional<PoseDatum> pose_;
  std::optional<LaserScan> laser_;
  std::optional<BatteryDatum> battery_;
  double stamp_[kSensorKinds] = {0, 0, 0, 0};
  std::vector<SonarLine> lines_;
  bool lines_valid_ = false;
};

}  // namespace rpl_executive::noreils_chatila
