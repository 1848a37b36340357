// pair_style granthesis: the thesis' contact laws (viscoelastic Hertz or the linear spring-dashpot,
// with the Coulomb-capped viscous friction) inside LAMMPS, evaluated by the same code as the native
// engine (src/talus). Syntax and conventions: lammps-package/README.md.
// The style block lets the file drop into a LAMMPS source tree as a package: LAMMPS includes
// its style headers once to declare the classes and once with PAIR_CLASS defined to
// register them (so no #pragma once here).
#ifdef PAIR_CLASS
// clang-format off
PairStyle(granthesis, talus::lammps::PairGranthesis);
// clang-format on
#else
#ifndef TALUS_LAMMPS_PAIR_GRANTHESIS_H
#define TALUS_LAMMPS_PAIR_GRANTHESIS_H
#include <source_location>
#include <string>
#include <vector>

#include "host_api.hpp"
#include "talus/law_table.hpp"
#include "talus/material.hpp"
#include "talus/pair_parameters.hpp"

namespace talus::lammps {

class PairGranthesis : public HostPair {
public:
  explicit PairGranthesis(LAMMPS_NS::LAMMPS* instance);
  ~PairGranthesis() override;

  void compute(int eflag, int vflag) override;
  void settings(int narg, char** arg) override;
  void coeff(int narg, char** arg) override;
  void modify_params(int narg, char** arg) override;
  void init_style() override;
  double init_one(int i, int j) override;
  double single(int i, int j, int itype, int jtype, double rsq, double factor_coul,
                double factor_lj, double& fforce) override;
  void write_restart(FILE* file) override;
  void write_restart_settings(FILE* file) override;

  /// The pair parameters of types i and j (1-based), as mixed or given (after init_style).
  const PairParameters& parameters(int i, int j) const;
  /// Whether types i and j have pair parameters: both have materials, or the pair its own.
  bool has_parameters(int i, int j) const { return known_[slot(i, j)] != 0; }
  /// The lightest mass (kg) and smallest radius (m) of type t's atoms at init; 0 where none.
  double lightest_mass(int t) const { return lightest_[static_cast<std::size_t>(t)]; }
  double smallest_radius(int t) const {
    return lightest_[static_cast<std::size_t>(ntypes_ + 1 + t)];
  }
  /// The collision time (s) of a contact of pair parameters p, reduced mass m_eff and radius
  /// r_eff under the normal law (a Hertz one at the impact speed).
  double collision_time(const PairParameters& p, double m_eff, double r_eff) const;
  NormalLaw normal_law() const { return normal_; }
  TangentialLaw tangential_law() const { return tangential_; }
  double impact_speed() const { return impact_speed_; }
  /// The material pair_coeff I I gave type i (1-based).
  const Material& material(int i) const { return material_[static_cast<std::size_t>(i)]; }
  int history_slots() const { return history_slots_; }
  /// Whether some type pair has rolling resistance, from the coefficients given.
  bool rolling() const;
  /// Atom i's moment of inertia about a point of its rim, (k + 1) m R^2 with k = 1/2 for disks
  /// and 2/5 for spheres (pair_style keyword `inertia`): the rolling law's damping needs it.
  double rim_inertia(int i) const;

private:
  template <class N, class T> void compute_with(int eflag, int vflag);
  /// The same for spheres in 3D: springs, rolling angles, forces and torques as vectors
  /// (pair_granthesis_3d.cpp); compute_3d_pass chooses the law pair.
  template <class N, class T> void compute_3d(int eflag, int vflag);
  void compute_3d_pass(int eflag, int vflag);
  void allocate();
  void check_hybrid() const; ///< refuses a hybrid style that would count a contact twice
  void mix_pairs();          ///< every type pair's parameters that can be known, into pair_
  void find_lightest();      ///< lightest_ from the atoms present
  void check_timestep() const;
  void init_history(); ///< makes or finds the springs' fix, for a law that keeps them
  void init_rolling(); ///< the same for the rolling springs, where a pair has rolling resistance
  /// The rolling torque of the contact of i and j (1-based types itype, jtype) with geometry g
  /// and normal force fn, added to both atoms' torques; its spring's energy.
  template <class N>
  double add_rolling_torque(int i, int j, const PairParameters& p, const ContactGeometry& g,
                            double fn, bool advance);
  /// The same in 3D: the rolling part of the relative spin, the angle as a vector.
  template <class N>
  double add_rolling_torque_3d(int i, int j, const PairParameters& p, const ContactGeometry3& g,
                               double fn, bool advance);
  /// single() for spheres in 3D.
  double single_3d(int i, int j, int itype, int jtype, double rsq, double& fforce);
  /// The index of type pair (i, j) in pair_ and explicit_pair_.
  std::size_t slot(int i, int j) const {
    return static_cast<std::size_t>(i) * static_cast<std::size_t>(ntypes_ + 1) +
           static_cast<std::size_t>(j);
  }
  /// Stops the run naming this style; LAMMPS cites the caller's file and line.
  [[noreturn]] void fail(const std::string& message,
                         std::source_location at = std::source_location::current()) const;
  /// fail(), for atoms i and j touching with dz != 0: out of line, off the pair loop's path.
  [[noreturn, gnu::cold, gnu::noinline]] void out_of_plane(int i, int j, double dz) const;
  void read_settings(FILE* file) override;     ///< the laws, from a restart file
  void read_coefficients(FILE* file) override; ///< the laws and the coefficients

  NormalLaw normal_ = law_id<HertzViscoelastic>;
  TangentialLaw tangential_ = law_id<ViscousCoulomb>;
  double impact_speed_ = 1.0; ///< m/s: where a derived Hertz damping reaches the restitution
  int history_slots_ = 16;    ///< contacts with a spring an atom may have at once
  FixContactHistory* history_ = nullptr;     ///< the springs, for a law that keeps them
  FixContactHistory* rolling_fix_ = nullptr; ///< the rolling springs' angles, seen from each atom
  bool rolling_ = false;
  int inertia_ = 0;             ///< 0: from the dimension (disks in 2d), 1: disc, 2: sphere
  double inertia_factor_ = 0.5; ///< k of I = k m R^2, from inertia_ at init
  int ntypes_ = 0;
  std::vector<Material> material_;   ///< per type, 1-based
  std::vector<PairParameters> pair_; ///< (ntypes + 1)^2: mixed or given per pair
  std::vector<char> explicit_pair_;  ///< 1 where pair_coeff I J (I != J) gave the pair
  std::vector<char> known_;          ///< 1 where pair_ holds the pair's parameters (init_style)
  std::vector<double> lightest_;     ///< per type: the lightest mass, then the smallest radius
  /// 1 for the types whose material pair_coeff I I gave. LAMMPS' own setflag is 1 everywhere,
  /// so that its check before init_style passes and init_style names the type that is missing.
  std::vector<char> given_;
  double max_radius_ = 0.0; ///< the largest radius of any atom, or to be poured (m), at init
  /// single(): fx, fy, torque_i, torque_j, F_n, overlap in 2d; fx, fy, fz, |F_t|, F_n, overlap
  /// in 3d
  double svector_storage_[6] = {};
};

} // namespace talus::lammps

#endif // TALUS_LAMMPS_PAIR_GRANTHESIS_H
#endif // PAIR_CLASS
