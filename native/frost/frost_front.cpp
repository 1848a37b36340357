#include "frost/frost_front.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "frost/resting_pairs.hpp"
#include "talus/error.hpp"

namespace talus {

namespace {

constexpr std::size_t slices_per_depth = 200; // Stefan table resolution: D / 200

// Area of a disk of radius r centred at height yc between heights ya < yb.
double disk_area_between(double yc, double r, double ya, double yb) {
  const auto primitive = [&](double y) {
    const double s = std::clamp((y - yc) / r, -1.0, 1.0);
    return r * r * (s * std::sqrt(1.0 - s * s) + std::asin(s));
  };
  return primitive(yb) - primitive(ya);
}

// The top of the ground under grain s's lowest point: the highest point, on the vertical
// through s's centre, of the grains below it (-inf: none; s rests on a wall or nothing).
double ground_beneath(const Particles& p, std::size_t s) {
  double top = -std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < p.size(); ++j) {
    if (j == s || p.position[j].y >= p.position[s].y) continue;
    const double dx = std::abs(p.position[j].x - p.position[s].x), r = p.radius[j];
    if (dx < r) top = std::max(top, p.position[j].y + std::sqrt(r * r - dx * dx));
  }
  return top;
}

// Frozen grains feel no force from each other, so two that froze while pressed together (a free
// grain shoved against a frozen one by the heave below it, then frozen itself) keep that overlap
// to the thaw, where its elastic energy would shoot them apart: 36 um between two fines of the
// window box (9% of a radius, with k = 3e6 N/m) threw one out of the box at 1.3 m/s. A grain
// that thaws out is therefore first moved apart from the grains that were frozen with it, down
// to an overlap of 0.1% of the smaller radius (a contact loaded by the weight of the grains above
// it overlaps about 0.01% there); a pair that thaws together shares the move. Released grains are
// few per call, so every frozen grain is tried.
void separate_released(Particles& p, const std::vector<std::uint32_t>& released,
                       const std::vector<std::uint8_t>& frozen) {
  for (const std::uint32_t i : released)
    for (std::size_t j = 0; j < p.size(); ++j) {
      if (j == i || !frozen[j]) continue;
      const Vec2 d = p.position[i] - p.position[j];
      const double reach = p.radius[i] + p.radius[j];
      const double dist2 = norm2(d);
      if (dist2 >= reach * reach || dist2 == 0.0) continue;
      const double dist = std::sqrt(dist2);
      const double excess = reach - dist - 0.001 * std::min(p.radius[i], p.radius[j]);
      if (excess <= 0.0) continue;
      const Vec2 shift = d * (excess / dist);
      if (p.is_free(j)) { // released in this call too (i is before it or after it)
        p.position[i] += shift * 0.5;
        p.position[j] -= shift * 0.5;
      } else {
        p.position[i] += shift;
      }
    }
}

} // namespace

void check(const FrostFrontParameters& p) {
  const auto need = [](bool ok, const char* key, const char* allowed) {
    if (!ok) throw InvalidArgument(std::string("frost.") + key + ": allowed: " + allowed);
  };
  need(p.permafrost_depth > 0.0, "permafrost_depth", "> 0 m (the front model needs it)");
  need(p.heave_strain >= 0.0 && p.heave_strain <= 1.0, "heave_strain", "0 to 1");
  need(p.conductivity_ratio >= 1e-3 && p.conductivity_ratio <= 1e3, "conductivity_ratio",
       "1e-3 to 1e3 (stone / soil; 1: no contrast)");
  need(p.stone_water >= 0.0 && p.stone_water <= 1e3, "stone_water",
       "0 to 1e3 (stone / soil latent heat per volume; 0: dry stones)");
  need(p.ice_content >= 0.0 && p.ice_content <= 1.0, "ice_content",
       "0 to 1 (ice per volume of frozen fines; 0: their pore fraction in the bed)");
  need(p.crust_length >= 0.0, "crust_length",
       ">= 0 m (below the column width: each column on its own)");
  need(p.column_width > 0.0, "column_width", "> 0 m");
  need(p.stone_radius > 0.0, "stone_radius", "> 0 m");
  need(p.freeze_time > 0.0, "freeze_time", "> 0 s");
  need(p.thaw_time > 0.0, "thaw_time", "> 0 s");
  need(p.x_max > p.x_min, "columns", "a bed of positive width");
  need(p.thawed_material >= -1, "thawed_material", "a material's name");
}

FrostFront::FrostFront(FrostFrontParameters p) : p_(p) {
  check(p_);
  const auto n = static_cast<std::size_t>(
      std::max(1.0, std::ceil((p_.x_max - p_.x_min) / p_.column_width - 1e-9)));
  surface_.assign(n, 0.0);
  front_.assign(n, 0.0);
  heave_.assign(n, 0.0);
}

std::size_t FrostFront::column_of(double x) const {
  const double u = (x - p_.x_min) / p_.column_width;
  if (!(u > 0.0)) return 0;
  return std::min(surface_.size() - 1, static_cast<std::size_t>(u));
}

void FrostFront::lift_resting_grains(const Particles& p, std::vector<double>& up) const {
  // The lift passes through free grains too (they are not displaced here, but a free grain
  // caught between a frozen grain that rises and one above it that does not would be crushed):
  // each grain rises with the grains it rests on (resting_pairs.hpp).
  if (std::none_of(up.begin(), up.end(), [](double u) { return u != 0.0; })) return;
  std::vector<std::uint32_t> grains;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (frozen_[i] || p.is_free(i)) grains.push_back(static_cast<std::uint32_t>(i));
  if (grains.size() < 2) return;
  // cells two fine radii wide (the largest fine's diameter)
  double cell = 0.0;
  for (const std::uint32_t i : grains)
    if (!is_stone(p, i)) cell = std::max(cell, 2.0 * p.radius[i]);
  if (cell == 0.0) cell = 2.0 * p.max_radius();
  std::vector<std::pair<std::uint32_t, std::uint32_t>> rests =
      resting_pairs(p, grains, cell, p_.x_min, p_.x_max);
  // from the bottom up: a lower grain's lift is final before it is passed on
  std::sort(rests.begin(), rests.end(), [&](const auto& a, const auto& b) {
    return p.position[a.first].y < p.position[b.first].y ||
           (p.position[a.first].y == p.position[b.first].y && a < b);
  });
  for (const auto& [lower, upper] : rests) up[upper] = std::max(up[upper], up[lower]);
}

double FrostFront::heave_at(const std::vector<double>& h, double x) const {
  const double u = (x - p_.x_min) / p_.column_width - 0.5; // column centres at integers
  if (!(u > 0.0)) return h.front();
  const auto c = static_cast<std::size_t>(u);
  if (c + 1 >= h.size()) return h.back();
  const double t = u - static_cast<double>(c);
  return (1.0 - t) * h[c] + t * h[c + 1];
}

bool FrostFront::is_stone(const Particles& p, std::size_t i) const {
  return p.radius[i] >= p_.stone_radius;
}

void FrostFront::start_freeze(Simulation& sim) {
  if (sim.config().sort_interval != 0)
    throw InvalidArgument("the frost front model keeps its grains by index: it needs a run "
                          "without renumbering (simulation.sort_every = 0; a scenario with a "
                          "frost model sets it)");
  const Particles& p = sim.world().particles;
  if (material_.size() == p.size()) // thawed fines get their own material back
    for (std::size_t i = 0; i < p.size(); ++i)
      sim.edit_particles().set_material(static_cast<std::uint32_t>(i),
                                        static_cast<std::size_t>(material_[i]));
  material_.assign(p.material.begin(), p.material.end());
  frozen_.assign(p.size(), 0);
  find_surface(p);
  // the columns' make-up in slices below their surface: the area of stones and of fines
  const std::size_t n = surface_.size();
  std::vector<std::vector<double>> stone(n, std::vector<double>(slices_per_depth, 0.0)),
      fine(n, std::vector<double>(slices_per_depth, 0.0));
  slice_areas(p, stone, fine);
  ice_content_ = p_.ice_content != 0.0 ? p_.ice_content : pore_fraction(p, stone, fine);
  stefan_tables(stone, fine);
  std::fill(front_.begin(), front_.end(), 0.0);
  std::fill(heave_.begin(), heave_.end(), 0.0);
  phase_ = Phase::freezing;
  phase_start_ = sim.time();
}

void FrostFront::find_surface(const Particles& p) {
  const std::size_t n = surface_.size();
  // each column's surface: the top of its highest free fine (a stone sticking out does not
  // count; a column without fines: the bed's top)
  double top = -1e300;
  std::vector<double> surface(n, -1e300);
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.is_free(i) && !is_stone(p, i)) {
      const double y = p.position[i].y + p.radius[i];
      top = std::max(top, y);
      double& s = surface[column_of(p.position[i].x)];
      s = std::max(s, y);
    }
  if (top == -1e300) throw InvalidArgument("frost: there are no free grains to freeze");
  for (auto& s : surface)
    if (s == -1e300) s = top;
  surface_ = surface;
  dz_ = p_.permafrost_depth / static_cast<double>(slices_per_depth);
}

void FrostFront::slice_areas(const Particles& p, std::vector<std::vector<double>>& stone,
                             std::vector<std::vector<double>>& fine) const {
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!p.is_free(i)) continue;
    const std::size_t c = column_of(p.position[i].x);
    const double r = p.radius[i], y = p.position[i].y;
    const double z_top = surface_[c] - (y + r), z_bottom = surface_[c] - (y - r);
    const auto k0 = static_cast<std::ptrdiff_t>(std::floor(z_top / dz_));
    const auto k1 = static_cast<std::ptrdiff_t>(std::floor(z_bottom / dz_));
    for (std::ptrdiff_t k = std::max<std::ptrdiff_t>(0, k0);
         k <= std::min<std::ptrdiff_t>(k1, slices_per_depth - 1); ++k) {
      const double ya = surface_[c] - static_cast<double>(k + 1) * dz_, yb = ya + dz_;
      (is_stone(p, i) ? stone : fine)[c][static_cast<std::size_t>(k)] +=
          disk_area_between(y, r, ya, yb);
    }
  }
}

double FrostFront::pore_fraction(const Particles& p, const std::vector<std::vector<double>>& stone,
                                 const std::vector<std::vector<double>>& fine) const {
  const std::size_t n = surface_.size();
  double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo, fine_r = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.is_free(i)) {
      x_lo = std::min(x_lo, p.position[i].x - p.radius[i]);
      x_hi = std::max(x_hi, p.position[i].x + p.radius[i]);
      if (!is_stone(p, i)) fine_r = std::max(fine_r, p.radius[i]);
    }
  double band = 0.0, fine_area = 0.0, stone_area = 0.0;
  for (std::size_t c = 0; c < n; ++c) {
    const double c_lo = std::max(x_lo, p_.x_min + static_cast<double>(c) * p_.column_width);
    const double c_hi = std::min(x_hi, c_lo + p_.column_width);
    for (std::size_t k = 0; k < slices_per_depth; ++k)
      if (static_cast<double>(k) * dz_ >= 2.0 * fine_r && stone[c][k] + fine[c][k] > 0.0) {
        band += std::max(0.0, c_hi - c_lo) * dz_;
        fine_area += fine[c][k];
        stone_area += stone[c][k];
      }
  }
  const double pores = band - stone_area - fine_area;
  return band > stone_area && pores > 0.0 ? pores / (band - stone_area) : 1.0;
}

void FrostFront::stefan_tables(const std::vector<std::vector<double>>& stone,
                               const std::vector<std::vector<double>>& fine) {
  const std::size_t n = surface_.size();
  // layered Stefan: the front needs (latent heat in the slice) x (thermal resistance above it);
  // stones hold no water and conduct conductivity_ratio times better than fines. In units where
  // a column of pure fines reaches depth z at time z^2 / 2.
  time_.assign(n, std::vector<double>(slices_per_depth + 1, 0.0));
  fines_.assign(n, std::vector<double>(slices_per_depth, 1.0));
  for (std::size_t c = 0; c < n; ++c) {
    double resistance = 0.0;
    for (std::size_t k = 0; k < slices_per_depth; ++k) {
      // an empty slice (below the floor) freezes like fines but has no fines to heave
      const double solids = stone[c][k] + fine[c][k];
      const double f = solids > 0.0 ? fine[c][k] / solids : 1.0;
      const double conductivity = f + p_.conductivity_ratio * (1.0 - f);
      const double latent = f + p_.stone_water * (1.0 - f);
      fines_[c][k] = solids > 0.0 ? f : 0.0;
      time_[c][k + 1] = time_[c][k] + latent * (resistance + 0.5 * dz_ / conductivity) * dz_;
      resistance += dz_ / conductivity;
    }
  }
}

double FrostFront::front_at(std::size_t c, double target) const {
  const std::vector<double>& t = time_[c];
  if (target >= t.back()) return p_.permafrost_depth;
  // the first slice whose end the front has not reached; slices of stone take no time
  const auto it = std::upper_bound(t.begin(), t.end(), target);
  const auto k = static_cast<std::size_t>(it - t.begin()) - 1;
  const double span = t[k + 1] - t[k];
  return (static_cast<double>(k) + (span > 0.0 ? (target - t[k]) / span : 1.0)) * dz_;
}

bool FrostFront::advance(Simulation& sim) {
  const Particles& p = sim.world().particles;
  if (phase_ == Phase::idle) return false;
  if (frozen_.size() != p.size()) frozen_.resize(p.size(), 0);
  const double elapsed = sim.time() - phase_start_;
  if (phase_ == Phase::freezing) {
    const double u = std::min(1.0, elapsed / p_.freeze_time);
    freeze(sim, u * 0.5 * p_.permafrost_depth * p_.permafrost_depth);
    if (u < 1.0) return false;
    start_thaw(sim);
    return true;
  }
  return thaw(sim, elapsed / p_.thaw_time);
}

std::vector<double> FrostFront::descend_front(double target) {
  const std::size_t n = surface_.size();
  std::vector<double> dh(n, 0.0);
  for (std::size_t c = 0; c < n; ++c) {
    const double next = std::max(front_[c], front_at(c, target));
    double fines = 0.0; // integral of the fine share over the crossed depth
    for (double z = front_[c]; z < next - 1e-15;) {
      const auto k = std::min(slices_per_depth - 1, static_cast<std::size_t>(z / dz_));
      const double end = std::min(next, static_cast<double>(k + 1) * dz_);
      fines += fines_[c][k] * (end - z);
      z = end > z ? end : next;
    }
    dh[c] = p_.heave_strain * fines;
    front_[c] = next;
  }
  return dh;
}

void FrostFront::freeze(Simulation& sim, double target) {
  const Particles& p = sim.world().particles;
  const std::size_t n = surface_.size();
  // heave from the fines the front crossed since the last call, column by column
  const std::vector<double> dh = descend_front(target);
  // grains the front has passed freeze: fines by their centre, stones by their top
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!p.is_free(i) || frozen_[i]) continue;
    const std::size_t c = column_of(p.position[i].x);
    const double depth = surface_[c] - p.position[i].y - (is_stone(p, i) ? p.radius[i] : 0.0);
    if (depth <= front_[c]) {
      sim.edit_particles().hold(static_cast<std::uint32_t>(i), true);
      frozen_[i] = 1;
    }
  }
  // the crust: stiff, so over ground that heaves less (a stone narrower than the crust) it is
  // carried by the lenses beside it: each column takes the largest heave within the crust
  // length on either side
  std::vector<double> smooth = dh;
  const auto reach = static_cast<std::size_t>(std::floor(p_.crust_length / p_.column_width + 1e-9));
  for (std::size_t c = 0; c < n; ++c)
    for (std::size_t k = c > reach ? c - reach : 0; k <= std::min(n - 1, c + reach); ++k)
      smooth[c] = std::max(smooth[c], dh[k]);
  for (std::size_t c = 0; c < n; ++c) heave_[c] += smooth[c];
  // every frozen grain moves up by the heave at its x, linear between the columns' centres,
  // and at least as much as any grain it rests on: held grains do not give way, so a grain
  // pushed from below by one that heaves more would be pressed into it, and the overlap would
  // burst out at the thaw
  std::vector<double> up(p.size(), 0.0);
  for (std::size_t i = 0; i < p.size(); ++i)
    if (frozen_[i]) up[i] = heave_at(smooth, p.position[i].x);
  lift_resting_grains(p, up);
  for (std::size_t i = 0; i < p.size(); ++i)
    if (frozen_[i] && up[i] != 0.0)
      sim.edit_particles().displace_held(static_cast<std::uint32_t>(i), {0.0, up[i]});
}

bool FrostFront::thaw(Simulation& sim, double u) {
  // from the heaved surface down to the bottom of the frozen layer in thaw_time (depth growing as
  // the root of time), and on below it, at the same law, while a stone's cavity ice (or the fines
  // under it) is left
  const Particles& p = sim.world().particles;
  bool held = false;
  std::vector<std::uint32_t> released; // still marked frozen_ until they are separated
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!frozen_[i]) continue;
    const std::size_t c = column_of(p.position[i].x);
    const double top = surface_[c] + heave_[c], bottom = surface_[c] - front_[c];
    const double thaw = top - (top - bottom) * std::sqrt(u);
    const bool stone = is_stone(p, i) && p_.frost_pull && i < release_level_.size();
    const double delay = i < thaw_delay_.size() ? thaw_delay_[i] : 0.0;
    const bool thawed = stone ? release_level_[i] >= thaw
                              : (u >= 1.0 && delay == 0.0) || p.position[i].y - delay >= thaw;
    if (!thawed) {
      held = true;
      continue;
    }
    sim.edit_particles().hold(static_cast<std::uint32_t>(i), false);
    released.push_back(static_cast<std::uint32_t>(i));
    if (p_.thawed_material >= 0 && !is_stone(p, i))
      sim.edit_particles().set_material(static_cast<std::uint32_t>(i),
                                        static_cast<std::size_t>(p_.thawed_material));
  }
  // it moves grains: edit_world has the next steps test the neighbour list against them
  if (!released.empty()) separate_released(sim.edit_world().particles, released, frozen_);
  for (const std::uint32_t i : released) frozen_[i] = 0;
  if (u < 1.0 || held) return false;
  phase_ = Phase::idle;
  return true;
}

void FrostFront::start_thaw(Simulation& sim) {
  // frost pull: the cavity the heave opened under a gripped stone holds segregation ice, and the
  // stone rests on it until the thaw has gone through it to the ground beneath (its lowest point
  // where nothing lies under it). That ice is pure: a thickness h of it holds the latent heat of
  // h / ice_content of frozen fines, so the thaw front, which advances through frozen fines,
  // must reach h (1 / ice_content - 1) below the cavity's floor before the stone is free. The
  // frozen fines under that ice, in the stone's shadow, thaw only after it: the thaw there is as
  // much later as the ice's extra latent heat.
  const Particles& p = sim.world().particles;
  release_level_.assign(p.size(), 0.0);
  thaw_delay_.assign(p.size(), 0.0);
  const double extra = 1.0 / ice_content_ - 1.0;
  for (std::size_t s = 0; s < p.size(); ++s)
    if (frozen_[s] && is_stone(p, s)) {
      const std::size_t c = column_of(p.position[s].x);
      const double frozen_bottom = surface_[c] - front_[c]; // no ice below the front
      const double lowest = p.position[s].y - p.radius[s];
      const double floor = std::min(lowest, std::max(frozen_bottom, ground_beneath(p, s)));
      const double delay = extra * (lowest - floor);
      release_level_[s] = floor - delay;
      if (!p_.frost_pull || delay <= 0.0) continue;
      for (std::size_t i = 0; i < p.size(); ++i)
        if (frozen_[i] && !is_stone(p, i) && p.position[i].y < floor &&
            std::abs(p.position[i].x - p.position[s].x) < p.radius[s])
          thaw_delay_[i] = std::max(thaw_delay_[i], delay);
    }
  phase_ = Phase::thawing;
  phase_start_ = sim.time();
}

std::vector<double> FrostFront::save() const {
  std::vector<double> out{static_cast<double>(phase_), phase_start_, dz_,
                          static_cast<double>(surface_.size()),
                          static_cast<double>(time_.empty() ? 0 : slices_per_depth)};
  for (const auto* v : {&surface_, &front_, &heave_}) out.insert(out.end(), v->begin(), v->end());
  for (const auto& t : time_) out.insert(out.end(), t.begin(), t.end());
  for (const auto& f : fines_) out.insert(out.end(), f.begin(), f.end());
  out.push_back(static_cast<double>(frozen_.size()));
  for (const auto f : frozen_) out.push_back(f);
  out.push_back(static_cast<double>(material_.size()));
  out.insert(out.end(), material_.begin(), material_.end());
  out.push_back(static_cast<double>(release_level_.size()));
  out.insert(out.end(), release_level_.begin(), release_level_.end());
  out.push_back(ice_content_);
  out.push_back(static_cast<double>(thaw_delay_.size()));
  out.insert(out.end(), thaw_delay_.begin(), thaw_delay_.end());
  return out;
}

void FrostFront::load(const std::vector<double>& v, std::size_t particles) {
  const auto bad = [] { throw std::runtime_error("frost front state: malformed in checkpoint"); };
  if (v.size() < 5) bad();
  const auto n = static_cast<std::size_t>(v[3]), slices = static_cast<std::size_t>(v[4]);
  if (n != surface_.size() || (slices != 0 && slices != slices_per_depth)) bad();
  std::size_t k = 5;
  const auto take = [&](std::size_t count) {
    if (k + count > v.size()) bad();
    std::vector<double> out(v.begin() + static_cast<std::ptrdiff_t>(k),
                            v.begin() + static_cast<std::ptrdiff_t>(k + count));
    k += count;
    return out;
  };
  phase_ = static_cast<Phase>(static_cast<int>(v[0]));
  phase_start_ = v[1];
  dz_ = v[2];
  surface_ = take(n);
  front_ = take(n);
  heave_ = take(n);
  time_.clear();
  fines_.clear();
  if (slices) {
    for (std::size_t c = 0; c < n; ++c) time_.push_back(take(slices + 1));
    for (std::size_t c = 0; c < n; ++c) fines_.push_back(take(slices));
  }
  const auto count = static_cast<std::size_t>(take(1)[0]);
  if (count != 0 && count != particles) bad();
  frozen_.clear();
  for (const double f : take(count)) frozen_.push_back(static_cast<std::uint8_t>(f));
  const auto materials = static_cast<std::size_t>(take(1)[0]);
  if (materials != 0 && materials != particles) bad();
  material_ = take(materials);
  release_level_.clear();
  thaw_delay_.clear();
  ice_content_ = 1.0;        // older checkpoints: cavity ice thawed like frozen fines
  if (k == v.size()) return; // written before the ice under stones was kept: lowest points
  const auto stones = static_cast<std::size_t>(take(1)[0]);
  if (stones != 0 && stones != particles) bad();
  release_level_ = take(stones);
  if (k == v.size()) return; // written before the ice content was kept
  ice_content_ = take(1)[0];
  if (!(ice_content_ > 0.0 && ice_content_ <= 1.0)) bad();
  const auto delays = static_cast<std::size_t>(take(1)[0]);
  if (delays != 0 && delays != particles) bad();
  thaw_delay_ = take(delays);
}

} // namespace talus
