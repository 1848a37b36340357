// fix granthesis/wall: walls, fixed, translating, vibrating or turning, that act on the group's
// atoms with pair_style granthesis' laws and its materials, evaluated by the same code as the
// native engine's walls: in 2d straight segments (src/talus/segment_contact.hpp for where a grain
// touches), in 3d plates, whole planes or rectangles (src/talus/plate.hpp for where a sphere
// touches and how a plate moves; fix_granthesis_wall_3d.cpp); contact_force.hpp for the force.
// Syntax and conventions: lammps-package/README.md.
// The style block lets the file drop into a LAMMPS source tree as a package (so no #pragma once).
#ifdef FIX_CLASS
// clang-format off
FixStyle(granthesis/wall, talus::lammps::FixGranthesisWall);
// clang-format on
#else
#ifndef TALUS_LAMMPS_FIX_GRANTHESIS_WALL_H
#define TALUS_LAMMPS_FIX_GRANTHESIS_WALL_H
#include <optional>
#include <source_location>
#include <string>
#include <vector>

#include "fix.h"
#include "run_clock.hpp"
#include "segment_neighbours.hpp"
#include "talus/contact_geometry.hpp"
#include "talus/contact_geometry_3d.hpp"
#include "talus/pair_parameters.hpp"
#include "talus/plate.hpp"
#include "talus/segment_contact.hpp"

namespace talus::lammps {

class FixContactHistory;
class PairGranthesis;

namespace wall_words {
inline constexpr const char* style_name = "fix granthesis/wall";
inline constexpr const char* usage =
    "usage: fix ID GROUP granthesis/wall segment AX AY BX BY type T [velocity VX VY | rotate CX "
    "CY OMEGA | vibrate DX DY AMPLITUDE FREQUENCY PHASE] [segment ...] (2d), or plane PX PY PZ "
    "NX NY NZ type T [extent HALF_U HALF_V] [velocity VX VY VZ | rotate PX PY PZ WX WY WZ | "
    "vibrate DX DY DZ AMPLITUDE FREQUENCY PHASE] [plane ...] (3d)";
} // namespace wall_words

class FixGranthesisWall : public LAMMPS_NS::Fix {
public:
  FixGranthesisWall(LAMMPS_NS::LAMMPS* instance, int narg, char** arg);
  ~FixGranthesisWall() override;

  int setmask() override;
  void post_constructor() override;
  void init() override;
  void setup(int vflag) override;
  void post_force(int vflag) override;
  void end_of_step() override;
  double compute_scalar() override;
  double compute_vector(int n) override;
  void write_restart(FILE* file) override;
  void restart(char* buffer) override;

private:
  enum class Motion { none, translate, rotate, vibrate };
  /// A segment as the deck gives it, at the fix's start, and its motion.
  struct Wall {
    double ax, ay, bx, by; ///< end points at the start (m)
    int type;              ///< the atom type whose material (pair_coeff T T) the wall is of
    Motion motion = Motion::none;
    double vx = 0.0, vy = 0.0;              ///< translation (m/s)
    double cx = 0.0, cy = 0.0, omega = 0.0; ///< rotation about (cx, cy) (rad/s)
    double dx = 0.0, dy = 0.0;              ///< vibration: its direction, a unit vector
    double amplitude = 0.0, frequency = 0.0, phase = 0.0; ///< m, Hz, rad
  };
  /// A segment where it is now, and the velocity of its translation or vibration.
  struct Placed {
    double ax, ay, bx, by;
    double vx = 0.0, vy = 0.0; ///< m/s
  };
  /// A plate in 3d: where the deck puts it (at the fix's start), where it is now, its motion.
  struct PlateWall {
    PlatePose start;
    Plane now;
    std::optional<PlateDriver> driver;
    int type; ///< the atom type whose material (pair_coeff T T) the plate is of
  };
  /// Stops the run naming this style; LAMMPS cites the caller's file and line.
  [[noreturn]] void fail(const std::string& message,
                         std::source_location at = std::source_location::current()) const;
  double number(int narg, char** arg, int k, const char* what) const;
  int read_segment(int narg, char** arg, int k);
  int read_motion(int narg, char** arg, int k);
  int read_vibration(int narg, char** arg, int k, const std::string& which, double& amplitude,
                     double& frequency, double& phase) const;
  int read_plate(int narg, char** arg, int k);
  int read_plate_motion(int narg, char** arg, int k);
  Vec3 vector(int narg, char** arg, int k, const char* what) const;
  int read_type(int narg, char** arg, int k, const std::string& which) const;
  std::size_t wall_count() const { return three_d_ ? plates_.size() : walls_.size(); }
  int wall_type(std::size_t s) const { return three_d_ ? plates_[s].type : walls_[s].type; }
  const char* wall_word() const { return three_d_ ? "plane" : "segment"; }
  double now() const; ///< s: the simulation time, carried across restart files
  void place(double t);
  void place_plates(double t);
  void make_history();
  void check_timestep() const; ///< warns of a timestep too coarse for a wall contact
  /// fail(): atom i touches segment s, a type pair without parameters (pair_style hybrid).
  [[noreturn, gnu::cold, gnu::noinline]] void unknown_pair(int i, std::size_t s) const;
  template <class N, class T> void add_forces(bool advance);
  void publish_local();
  ContactGeometry geometry(int i, std::size_t s, double hx, double hy, double& wx,
                           double& wy) const;
  template <class N, class T> void refresh_normal_forces();
  void plate_pass(bool advance); ///< the 3d forces, for the run's laws
  void refresh_plate_pass();     ///< the 3d end_of_step()
  template <class N, class T> void add_plate_forces(bool advance);
  template <class N, class T> void refresh_plate_normal_forces();
  ContactGeometry3 plate_geometry(int i, std::size_t s, const Vec3& touch) const;
  template <class N>
  double add_plate_rolling_torque(int i, std::size_t s, const PairParameters& p,
                                  const ContactGeometry3& g, double fn, bool advance,
                                  double& power);
  void begin_local();

  bool three_d_ = false; ///< plates (dimension 3) rather than segments
  std::vector<Wall> walls_;
  std::vector<PlateWall> plates_;
  std::vector<Placed> placed_;
  std::vector<SegmentHit> hits_; ///< one atom's hits on its row's segments, scratch
  SegmentNeighbours near_;       ///< the segments near each atom
  double start_ = 0.0;           ///< s: the time at which the walls are where the deck puts them
  RunClock clock_;
  PairGranthesis* pair_ = nullptr;
  FixContactHistory* history_ = nullptr;
  std::string history_id_;
  FixContactHistory* rolling_ = nullptr; ///< the rolling springs, where a pair has some
  std::string rolling_id_;
  double energy_ = 0.0;          ///< J: elastic energy in the wall contacts (this rank's atoms)
  double work_ = 0.0;            ///< J: work the walls did on this rank's atoms so far
  double force_[3] = {};         ///< N: force of this rank's atoms on the walls, last step
  double totals_[4] = {};        ///< compute_vector's values, summed over ranks
  std::vector<double> contacts_; ///< per atom: segments touched in the last step
  /// The local array's columns: the atom's id, the wall (from 1), the normal force F_n (N),
  /// the overlap (m), and the contact's point on the wall (x, y, and in 3d z, m).
  int columns_ = 6;
  std::vector<double> local_;       ///< the last step's wall contacts, a row after another
  std::vector<double*> local_rows_; ///< array_local: the rows of local_
  std::vector<int> local_atom_;     ///< each row's atom (its local index)
  LAMMPS_NS::bigint summed_step_ = -1;
};

} // namespace talus::lammps

#endif // TALUS_LAMMPS_FIX_GRANTHESIS_WALL_H
#endif // FIX_CLASS
