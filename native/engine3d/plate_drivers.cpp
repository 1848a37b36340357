#include "engine3d/plate_drivers.hpp"

#include <string>

#include "talus/error.hpp"

namespace talus {

void require_plate(const std::string& which, std::uint32_t plate, std::size_t plates) {
  require(plate < plates, which + ": plate " + std::to_string(plate) +
                              " does not exist; allowed: 0 to " + std::to_string(plates) + " - 1");
}

void validate(const std::vector<PlateDriver>& drivers, std::size_t plates) {
  std::vector<bool> driven(plates, false);
  for (std::size_t k = 0; k < drivers.size(); ++k) {
    const PlateDriver& d = drivers[k];
    const std::string which = "plate driver " + std::to_string(k);
    require_plate(which, d.plate, plates);
    require(!driven[d.plate], which + ": plate " + std::to_string(d.plate) +
                                  " has a driver already; allowed: one driver a plate");
    driven[d.plate] = true;
    if (d.motion != PlateDriver::Motion::vibrate) continue;
    require(norm(d.direction) > 0.0, which + ": a vibration's direction must not be zero");
    require(d.amplitude >= 0.0 && d.frequency >= 0.0,
            which + ": a vibration's amplitude and frequency must be >= 0 (m, Hz)");
  }
}

void drive_plates(std::vector<Plane>& plates, const std::vector<PlateDriver>& drivers,
                  const std::vector<PlatePose>& start, double t) {
  for (const PlateDriver& d : drivers) place_plate(plates[d.plate], d, start[d.plate], t);
}

} // namespace talus
