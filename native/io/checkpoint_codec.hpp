#pragma once
// The pieces of the checkpoint files that the 2D and the 3D checkpoints share: the writer and
// reader of their fields, the checksum, the materials. Internal to io/.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "io/checkpoint.hpp"
#include "materials/material.hpp"

namespace talus::checkpoint_codec {

// FNV-1a's 64-bit offset basis. Format 7 was written with a basis one digit short (still a
// working checksum), so a file of that version is checked with the basis it was written with.
constexpr std::uint64_t fnv_offset_basis = 14695981039346656037ULL;
constexpr std::uint64_t format7_offset_basis = 1469598103934665603ULL;
constexpr std::uint32_t oldest_readable_version = 7; // with its basis and layout (below)

inline std::uint64_t fnv1a(const char* data, std::size_t n,
                           std::uint64_t basis = fnv_offset_basis) {
  std::uint64_t h = basis;
  for (std::size_t k = 0; k < n; ++k)
    h = (h ^ static_cast<unsigned char>(data[k])) * 1099511628211ULL;
  return h;
}

/// A checkpoint file's header: its format version and payload size, after an 8-byte magic word.
struct Header {
  std::uint32_t version = 0;
  std::uint64_t size = 0;
};
inline constexpr std::size_t header_bytes = 8 + sizeof(std::uint32_t) + sizeof(std::uint64_t);

/// The magic word, the version, the payload's size, the payload and its checksum.
inline std::string seal(const char* magic, std::uint32_t version, const std::string& payload) {
  std::string out(magic, 8);
  const std::uint64_t size = payload.size(), sum = fnv1a(payload.data(), payload.size());
  out.append(reinterpret_cast<const char*>(&version), sizeof(version));
  out.append(reinterpret_cast<const char*>(&size), sizeof(size));
  out += payload;
  out.append(reinterpret_cast<const char*>(&sum), sizeof(sum));
  return out;
}
/// The header of bytes that start with `magic`; throws CheckpointError ("not a KIND") otherwise.
inline Header read_header(const std::string& bytes, const char* magic, const std::string& source,
                          const std::string& kind) {
  if (bytes.size() < header_bytes + sizeof(std::uint64_t) || bytes.compare(0, 8, magic, 8) != 0)
    throw CheckpointError(source + ": not a " + kind + " (or truncated)");
  Header h;
  std::memcpy(&h.version, bytes.data() + 8, sizeof(h.version));
  std::memcpy(&h.size, bytes.data() + 8 + sizeof(h.version), sizeof(h.size));
  return h;
}
/// Throws CheckpointError unless the payload is whole and its checksum (with `basis`) holds.
inline void check_payload(const std::string& bytes, const Header& h, const std::string& source,
                          std::uint64_t basis = fnv_offset_basis) {
  std::uint64_t sum = 0;
  if (h.size != bytes.size() - header_bytes - sizeof(sum))
    throw CheckpointError(source + ": corrupt checkpoint: truncated or padded (size mismatch)");
  std::memcpy(&sum, bytes.data() + header_bytes + h.size, sizeof(sum));
  if (sum != fnv1a(bytes.data() + header_bytes, h.size, basis))
    throw CheckpointError(source + ": corrupt checkpoint: checksum mismatch");
}

class Writer {
public:
  template <class T> void pod(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    out_.append(reinterpret_cast<const char*>(&v), sizeof(T));
  }
  template <class T> void vec(const std::vector<T>& v) {
    pod<std::uint64_t>(v.size());
    if (!v.empty()) out_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
  void str(const std::string& s) {
    pod<std::uint64_t>(s.size());
    out_.append(s);
  }
  std::string& bytes() { return out_; }

private:
  std::string out_;
};

class Reader {
public:
  Reader(const std::string& bytes, std::size_t begin, std::size_t end, std::string source)
      : b_(bytes), at_(begin), end_(end), source_(std::move(source)) {}
  template <class T> T pod() {
    need(sizeof(T));
    T v;
    std::memcpy(&v, b_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return v;
  }
  template <class T> void vec(std::vector<T>& v) {
    const auto n = pod<std::uint64_t>();
    if (n > (end_ - at_) / std::max<std::size_t>(sizeof(T), 1)) fail("an array runs past the end");
    v.resize(n);
    if (n) std::memcpy(v.data(), b_.data() + at_, n * sizeof(T));
    at_ += n * sizeof(T);
  }
  /// A count of records that take at least `min_bytes` each: refused when they could not fit in
  /// what is left (so that a damaged count never asks for more memory than the file holds).
  std::size_t count(std::size_t min_bytes) {
    const auto n = pod<std::uint64_t>();
    if (n > (end_ - at_) / min_bytes) fail("a count of records runs past the end");
    return static_cast<std::size_t>(n);
  }
  std::string str() {
    const auto n = pod<std::uint64_t>();
    need(n);
    std::string s = b_.substr(at_, n);
    at_ += n;
    return s;
  }
  /// One member of a struct stored member by member: a bool is a byte that must be 0 or 1.
  template <class T> void member(T& v) {
    if constexpr (std::is_same_v<T, bool>) {
      const auto b = pod<std::uint8_t>();
      if (b > 1) fail("a flag is neither 0 nor 1");
      v = b == 1;
    } else {
      v = pod<T>();
    }
  }
  bool done() const { return at_ == end_; }
  [[noreturn]] void fail(const std::string& what) const {
    throw CheckpointError(source_ + ": corrupt checkpoint: " + what);
  }

private:
  void need(std::size_t n) const {
    if (n > end_ - at_) fail("truncated");
  }
  const std::string& b_;
  std::size_t at_, end_;
  std::string source_;
};

template <class T, class U>
concept either = std::is_same_v<std::remove_const_t<T>, U>;
/// Fields written one by one (a bool as a byte 0 or 1): a struct with padding is stored so,
/// field by field, so that no padding byte (of unspecified value) reaches the file.
template <class... T> void write_fields(Writer& w, const T&... v) {
  const auto one = [&](const auto& x) {
    if constexpr (std::is_same_v<std::decay_t<decltype(x)>, bool>)
      w.pod<std::uint8_t>(x ? 1 : 0);
    else
      w.pod(x);
  };
  (one(v), ...);
}
template <class... T> void read_fields(Reader& r, T&... v) {
  (r.member(v), ...);
}

inline void write_material(Writer& w, const Material& m) {
  w.str(m.name);
  for (const double v :
       {m.density, m.young, m.poisson, m.restitution, m.friction, m.tangential_damping,
        m.normal_stiffness, m.tangential_stiffness_ratio, m.normal_damping_rate, m.hertz_damping,
        m.rolling_friction, m.rolling_stiffness_factor, m.rolling_damping})
    w.pod(v);
  w.pod<std::uint8_t>(m.rigid ? 1 : 0);
}

// Format 11 added rolling resistance; a material of an older file has none (the keys' defaults).
inline Material read_material(Reader& r, std::uint32_t version) {
  Material m;
  m.name = r.str();
  for (double* v : {&m.density, &m.young, &m.poisson, &m.restitution, &m.friction,
                    &m.tangential_damping, &m.normal_stiffness, &m.tangential_stiffness_ratio,
                    &m.normal_damping_rate, &m.hertz_damping})
    *v = r.pod<double>();
  if (version >= 11)
    for (double* v : {&m.rolling_friction, &m.rolling_stiffness_factor, &m.rolling_damping})
      *v = r.pod<double>();
  m.rigid = r.pod<std::uint8_t>() != 0;
  return m;
}

} // namespace talus::checkpoint_codec
