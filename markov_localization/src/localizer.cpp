#include "markov_localization/localizer.h"
#include "markov_localization/validation.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace markov_localization {

std::vector<std::string> ValidateParameters(const MotionGateParameters& p) {
  std::vector<std::string> errors;
  if (!(p.update_min_d_m >= 0.0 && p.update_min_d_m <= 10.0))
    errors.push_back("update_min_d_m must be in [0, 10] m");
  if (!(p.update_min_a_rad >= 0.0 && p.update_min_a_rad <= 2.0 * M_PI))
    errors.push_back("update_min_a_rad must be in [0, 2 pi] rad");
  if (!(p.standing_interval_s >= 0.0 && p.standing_interval_s <= 3600.0))
    errors.push_back("standing_interval_s must be in [0, 3600] s");
  if (!(p.join_s >= 0.0 && p.join_s <= 5.0)) errors.push_back("join_s must be in [0, 5] s");
  return errors;
}

std::vector<std::string> ValidateParameters(const LocalizerParameters& p) {
  std::vector<std::string> errors;
  for (const auto& e : ValidateParameters(p.grid)) errors.push_back("grid." + e);
  for (const auto& e : ValidateParameters(p.gate)) errors.push_back("gate." + e);
  for (const auto& e : ValidateParameters(p.certainty)) errors.push_back("certainty." + e);
  if (!(p.modes.uniform_factor > 0.0)) errors.push_back("modes.uniform_factor must be > 0");
  if (!(p.modes.max_fraction >= 0.0 && p.modes.max_fraction < 1.0))
    errors.push_back("modes.max_fraction must be in [0, 1)");
  if (p.modes.max_modes < 1) errors.push_back("modes.max_modes must be >= 1");
  if (!(p.sticky.switch_ratio >= 1.0)) errors.push_back("sticky.switch_ratio must be >= 1");
  for (const auto& e : ValidateParameters(p.refine)) errors.push_back("refine." + e);
  return errors;
}

std::shared_ptr<const LocalizationModels> LocalizationModels::Build(
    std::shared_ptr<const MapModel> map, const std::vector<SensorModelParameters>& sensor_params,
    int num_headings) {
  if (!map) throw std::invalid_argument("LocalizationModels: no map");
  if (sensor_params.empty()) throw std::invalid_argument("LocalizationModels: no sensor");
  auto m = std::make_shared<LocalizationModels>();
  m->map = std::move(map);
  m->num_headings = num_headings;
  for (const auto& p : sensor_params)
    m->sensors.push_back(std::make_unique<SensorModel>(*m->map, num_headings, p));
  return m;
}

std::shared_ptr<const LocalizationModels> LocalizationModels::Build(
    std::shared_ptr<const MapModel> map, const std::vector<SensorModelParameters>& sensor_params,
    int num_headings, const std::shared_ptr<const LocalizationModels>& previous) {
  const bool reuse = previous && map && previous->map && previous->num_headings == num_headings &&
                     previous->sensors.size() == sensor_params.size() &&
                     map->SameRaster(*previous->map);
  if (!reuse) return Build(std::move(map), sensor_params, num_headings);
  for (std::size_t i = 0; i < sensor_params.size(); ++i)
    if (!(sensor_params[i] == previous->sensors[i]->parameters()))
      return Build(std::move(map), sensor_params, num_headings);
  auto m = std::make_shared<LocalizationModels>();
  m->map = std::move(map);
  m->num_headings = num_headings;
  for (const auto& s : previous->sensors)
    m->sensors.push_back(std::make_unique<SensorModel>(*s, *previous->map, *m->map));
  return m;
}

Localizer::Localizer(std::shared_ptr<const LocalizationModels> models,
                     const LocalizerParameters& params)
    : models_(std::move(models)), params_(params), sticky_(params.sticky) {
  const auto errors = ValidateParameters(params);
  ThrowIfInvalid(errors);
  if (!models_ || models_->sensors.empty())
    throw std::invalid_argument("Localizer: models without a sensor");
  grid_ = std::make_unique<MarkovGrid>(*models_->map, *models_->sensors[0], params.grid);
  pending_.resize(models_->sensors.size());
  judged_.assign(models_->sensors.size(), 1);
  for (int s : params.unjudged_sensors) {
    if (s < 0 || s >= static_cast<int>(judged_.size()))
      throw std::invalid_argument("Localizer: unjudged sensor " + std::to_string(s) + " of " +
                                  std::to_string(judged_.size()) + " sensors");
    judged_[s] = 0;
  }
}

void Localizer::ReplaceModels(std::shared_ptr<const LocalizationModels> models) {
  if (!models || models->sensors.size() != models_->sensors.size())
    throw std::invalid_argument("Localizer::ReplaceModels: other sensors");
  auto grid = std::make_unique<MarkovGrid>(*models->map, *models->sensors[0], params_.grid);
  if (grid->nt() != grid_->nt())
    throw std::invalid_argument("Localizer::ReplaceModels: another heading count");
  // The old belief at the centre of every new state cell.
  const MapModel& old_map = *models_->map;
  const MapModel& map = *models->map;
  std::vector<float> dense(static_cast<std::size_t>(grid->nx()) * grid->ny() * grid->nt(), 0.0f);
  std::vector<long> source(map.NumCells(), -1);
  for (int iy = 0; iy < map.height(); ++iy)
    for (int ix = 0; ix < map.width(); ++ix) {
      if (!map.IsState(ix, iy)) continue;
      const auto cell = old_map.CellOf(map.CellCentre(ix, iy));
      if (cell && old_map.IsState(cell->first, cell->second))
        source[map.Index(ix, iy)] = static_cast<long>(old_map.Index(cell->first, cell->second));
    }
  for (int k = 0; k < grid->nt(); ++k)
    for (int iy = 0; iy < map.height(); ++iy)
      for (int ix = 0; ix < map.width(); ++ix) {
        const long s = source[map.Index(ix, iy)];
        if (s < 0) continue;
        const int ox = static_cast<int>(s % old_map.width());
        const int oy = static_cast<int>(s / old_map.width());
        dense[(static_cast<std::size_t>(k) * grid->ny() + iy) * grid->nx() + ix] =
            static_cast<float>(grid_->Probability(ox, oy, k));
      }
  grid->SetBelief(dense);
  models_ = std::move(models);
  grid_ = std::move(grid);
  pending_.assign(models_->sensors.size(), Pending{});
  opener_ = -1;
  gate_opened_s_ = -1.0;
  force_ = true;
}

void Localizer::SetUniform() {
  grid_->SetUniform();
  sticky_.Reset();
  has_estimate_ = false;
  force_ = true;
}

void Localizer::SetGaussian(const Pose2& pose, double sigma_xy_m, double sigma_theta_rad,
                            const std::optional<Pose2>& at_odom) {
  grid_->SetGaussian(pose, sigma_xy_m, sigma_theta_rad);
  sticky_.Reset();
  has_estimate_ = false;
  force_ = true;
  // The motion since the last update belongs to the old belief, not to this one.
  has_update_odom_ = at_odom.has_value();
  if (at_odom) update_odom_ = *at_odom;
}

bool Localizer::GateOpen(const Pose2& odom, double now_s) const {
  if (force_ || !has_update_odom_) return true;
  const Motion m = MotionBetween(update_odom_, odom);
  if (std::hypot(m.dx, m.dy) >= params_.gate.update_min_d_m) return true;
  if (std::abs(m.dtheta) >= params_.gate.update_min_a_rad) return true;
  // Only a robot that stands: one that drives slowly would be updated every interval after a
  // few cm, and the corridor lock came back (at 0.12 m/s the estimate stayed put for 5 m along
  // cim_office's hallway, twice in one run).
  const double interval = params_.gate.standing_interval_s;
  return standing_ && interval > 0.0 && now_s - update_time_s_ >= interval;
}

LocalizerStep Localizer::OnReading(int sensor, const std::vector<double>& ranges_m,
                                   const Pose2& odom, double now_s, double turn_rad) {
  if (sensor < 0 || sensor >= static_cast<int>(pending_.size()))
    throw std::invalid_argument("Localizer::OnReading: no sensor " + std::to_string(sensor));
  if (static_cast<int>(ranges_m.size()) != models_->sensors[sensor]->num_beams())
    throw std::invalid_argument("Localizer::OnReading: " + std::to_string(ranges_m.size()) +
                                " readings for sensor " + std::to_string(sensor) + " of " +
                                std::to_string(models_->sensors[sensor]->num_beams()) + " beams");
  if (!std::isfinite(turn_rad))
    throw std::invalid_argument("Localizer::OnReading: a reading turned by a non-finite angle");
  // Standing: slower than 2 cm/s and 3 deg/s since the previous reading of any sensor (a
  // reading older than that one, a profile joining late, leaves the judgement as it was).
  if (has_last_reading_ && now_s > last_reading_s_) {
    const Motion m = MotionBetween(last_reading_odom_, odom);
    const double dt = now_s - last_reading_s_;
    standing_ = std::hypot(m.dx, m.dy) < 0.02 * dt && std::abs(m.dtheta) < 0.05 * dt;
  }
  if (!has_last_reading_ || now_s > last_reading_s_) {
    has_last_reading_ = true;
    last_reading_s_ = now_s;
    last_reading_odom_ = odom;
  }
  Pending& p = pending_[sensor];
  const bool twice = p.fresh && opener_ == sensor;
  p.ranges = ranges_m;
  p.odom = odom;
  p.turn_rad = turn_rad;
  p.fresh = true;
  p.time_s = now_s;
  if (!GateOpen(odom, now_s)) return LocalizerStep{};
  if (params_.gate.join_s > 0.0) {
    if (gate_opened_s_ < 0.0) gate_opened_s_ = now_s;
    bool all = true;  // every sensor's reading since the gate opened is here
    for (std::size_t s = 0; s < pending_.size(); ++s) all = all && Joins(s);
    if (!all && now_s - gate_opened_s_ < params_.gate.join_s) return LocalizerStep{};
    return Update(odom, now_s);
  }
  bool all = true;
  for (const auto& q : pending_) all = all && q.fresh;
  if (!all && !twice) {
    if (opener_ < 0) opener_ = sensor;  // wait for the other sensors' readings of this moment
    return LocalizerStep{};
  }
  return Update(odom, now_s);
}

bool Localizer::Joins(std::size_t s) const {
  const Pending& p = pending_[s];
  return p.fresh && (params_.gate.join_s <= 0.0 || p.time_s >= gate_opened_s_);
}

LocalizerStep Localizer::Update(const Pose2& odom, double now_s) {
  LocalizerStep step;
  step.updated = true;
  const int resets_before = grid_->forced_resets();
  if (has_update_odom_) {
    const Motion m = MotionBetween(update_odom_, odom);
    if (std::hypot(m.dx, m.dy) > 1e-4 || std::abs(m.dtheta) > 1e-4) grid_->MotionUpdate(m);
  }
  std::vector<SensorReading> readings;
  for (std::size_t s = 0; s < pending_.size(); ++s) {
    if (!Joins(s)) continue;
    readings.push_back(SensorReading{models_->sensors[s].get(), &pending_[s].ranges,
                                     judged_[s] != 0, pending_[s].turn_rad});
  }
  step.sensors_used = static_cast<int>(readings.size());
  const bool motion_reset = grid_->forced_resets() != resets_before;
  const std::string motion_reason = motion_reset ? grid_->lost_reason() : std::string();
  step.stats = grid_->SensorUpdateWith(readings);
  for (auto& p : pending_) p.fresh = false;
  opener_ = -1;
  gate_opened_s_ = -1.0;
  force_ = false;
  has_update_odom_ = true;
  update_odom_ = odom;
  update_time_s_ = now_s;
  ++updates_;
  if (motion_reset || step.stats.lost_detected) {
    step.lost = true;
    step.lost_reason = motion_reset ? motion_reason : step.stats.lost_reason;
    sticky_.Reset();
  }
  summary_ = Summarize(*grid_, params_.certainty, params_.modes, /*with_entropy=*/false);
  const auto& c = summary_.certainty;
  if (!step.stats.lost_detected &&
      grid_->ReportCertainty(c.certainty, params_.certainty.threshold)) {
    step.lost = true;
    step.lost_reason = grid_->lost_reason();
    sticky_.Reset();
    summary_ = Summarize(*grid_, params_.certainty, params_.modes, /*with_entropy=*/false);
  }
  // The pose below the cell size from this update's readings (pose_refinement.h).
  // Only with the beams the update used: the distance filter's short readings (an unmapped
  // desk) would pull the pose towards them by up to the refinement's cell.
  const Pose2 refined = RefinePose(*models_->map, readings, c.estimate, grid_->angular_resolution(),
                                   params_.refine, &step.stats.beam_used);
  // The published estimate stays with the mode it followed while twins swap the maximum.
  const Pose2 estimate = sticky_.Select(summary_.modes, refined, odom, &step.switched);
  map_to_odom_ = MapToOdom(estimate, odom);
  best_map_to_odom_ = MapToOdom(refined, odom);
  has_estimate_ = true;
  return step;
}

}  // namespace markov_localization
