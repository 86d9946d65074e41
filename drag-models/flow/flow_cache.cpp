#include "flow/flow_cache.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <system_error>

#include <unistd.h>

namespace hsrod {
namespace {

constexpr char kMagic[8] = {'H', 'S', 'R', 'O', 'D', 'B', 'F', '1'};
constexpr std::uint32_t kFormatVersion = 1;

std::uint64_t hash_arrays(const StaggeredField& f) {
  std::uint64_t h = fnv1a64(f.u_ext().data(), f.u_ext().size() * sizeof(double));
  h = fnv1a64(f.v_ext().data(), f.v_ext().size() * sizeof(double), h);
  return fnv1a64(f.p_ext().data(), f.p_ext().size() * sizeof(double), h);
}

template <class T>
bool read_pod(std::istream& in, T& value) {
  return static_cast<bool>(in.read(reinterpret_cast<char*>(&value), sizeof(T)));
}
template <class T>
void write_pod(std::ostream& out, const T& value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}
bool read_doubles(std::istream& in, std::vector<double>& v, std::size_t n) {
  v.resize(n);
  return static_cast<bool>(in.read(reinterpret_cast<char*>(v.data()), n * sizeof(double)));
}
void write_doubles(std::ostream& out, const std::vector<double>& v) {
  out.write(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(double));
}

}  // namespace

std::uint64_t fnv1a64(const void* data, std::size_t size, std::uint64_t seed) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  std::uint64_t h = seed;
  for (std::size_t k = 0; k < size; ++k) {
    h ^= bytes[k];
    h *= 1099511628211ull;
  }
  return h;
}

std::string brinkman_cache_key(const ChannelGeometry& geo, const MacGrid& grid,
                               double inertia_reynolds, bool exponential_wall_layer) {
  std::ostringstream k;
  k.precision(17);
  k << "hsrod depth-averaged Brinkman field; scheme " << kBrinkmanSchemeVersion
    << "; units H, U, mu U/H; L " << geo.length() << "; W " << geo.width() << "; cylinders "
    << geo.cylinders().size();
  for (const ZCylinder& c : geo.cylinders())
    k << " (" << c.center_x - geo.x_lo() << ' ' << c.center_y - geo.y_lo() << ' ' << c.radius
      << ')';
  k << "; grid " << grid.nx << 'x' << grid.ny << " h " << grid.hx << ' ' << grid.hy
    << "; inertia Re_H " << inertia_reynolds;
  if (exponential_wall_layer) k << "; wall layer exponentially fitted";
  return k.str();
}

std::string brinkman_cache_file_name(const std::string& key) {
  char name[64];
  std::snprintf(name, sizeof name, "brinkman-%016llx.bin",
                static_cast<unsigned long long>(fnv1a64(key.data(), key.size())));
  return name;
}

std::filesystem::path default_cache_directory() {
  auto env = [](const char* name) -> std::string {
    const char* v = std::getenv(name);
    return v ? std::string(v) : std::string();
  };
  if (!env("HSROD_CACHE_DIR").empty()) return env("HSROD_CACHE_DIR");
  if (!env("XDG_CACHE_HOME").empty()) return std::filesystem::path(env("XDG_CACHE_HOME")) / "hsrod";
  if (!env("HOME").empty()) return std::filesystem::path(env("HOME")) / ".cache" / "hsrod";
  return {};
}

std::optional<StaggeredField> load_cached_field(const std::filesystem::path& file,
                                                const std::string& key, std::string* why_unused) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  auto unused = [&](const char* why) -> std::optional<StaggeredField> {
    if (why_unused) *why_unused = why;
    return std::nullopt;
  };
  char magic[8];
  std::uint32_t version = 0, key_length = 0;
  if (!in.read(magic, 8) || std::string(magic, 8) != std::string(kMagic, 8)) return unused("not an hsrod field file");
  if (!read_pod(in, version) || version != kFormatVersion) return unused("another file format version");
  if (!read_pod(in, key_length)) return unused("truncated");
  if (key_length != key.size()) return unused("holds another scene (file name hash collision)");
  std::string stored(key_length, '\0');
  if (!in.read(stored.data(), key_length)) return unused("truncated");
  if (stored != key) return unused("holds another scene (file name hash collision)");
  std::int32_t nx = 0, ny = 0;
  MacGrid g;
  if (!read_pod(in, nx) || !read_pod(in, ny) || !read_pod(in, g.hx) || !read_pod(in, g.hy))
    return unused("truncated");
  if (nx < 1 || ny < 1 || nx > (1 << 20) || ny > (1 << 20)) return unused("corrupt grid size");
  g.nx = nx;
  g.ny = ny;
  std::vector<double> u, v, p;
  if (!read_doubles(in, u, std::size_t(extended_u_lattice(g).size())) ||
      !read_doubles(in, v, std::size_t(extended_v_lattice(g).size())) ||
      !read_doubles(in, p, std::size_t(nx + 2) * ny))
    return unused("truncated");
  std::uint64_t checksum = 0;
  if (!read_pod(in, checksum)) return unused("truncated");
  StaggeredField field(g, std::move(u), std::move(v), std::move(p));
  if (hash_arrays(field) != checksum) return unused("corrupt (checksum mismatch)");
  std::error_code ec;
  std::filesystem::last_write_time(file, std::filesystem::file_time_type::clock::now(), ec);
  return field;
}

double cache_size_limit_bytes() {
  if (const char* v = std::getenv("HSROD_CACHE_MAX_MB")) {
    char* end = nullptr;
    const double mb = std::strtod(v, &end);
    if (end != v && *end == '\0' && mb > 0.0 && std::isfinite(mb)) return mb * 1e6;
  }
  return 2000e6;
}

std::string CachePruning::summary() const {
  if (files_removed == 0) return "";
  std::ostringstream s;
  s.precision(3);
  s << "removed " << files_removed << " least recently used cache file(s) (" << bytes_removed / 1e6
    << " MB) to keep the cache under its limit ($HSROD_CACHE_MAX_MB, " << bytes_kept / 1e6 << " MB kept)";
  return s.str();
}

CachePruning prune_cache_directory(const std::filesystem::path& dir, double limit_bytes,
                                   const std::filesystem::path& keep) {
  namespace fs = std::filesystem;
  CachePruning result;
  struct Entry {
    fs::path path;
    fs::file_time_type time;
    double bytes;
  };
  std::vector<Entry> files;
  std::error_code ec;
  const auto now = fs::file_time_type::clock::now();
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const fs::path path = it->path();
    const std::string name = path.filename().string();
    std::error_code e;
    const auto time = fs::last_write_time(path, e);
    if (e) continue;
    if (name.rfind("brinkman-", 0) == 0 && name.find(".bin.tmp.") != std::string::npos) {
      if (now - time > std::chrono::hours(1)) fs::remove(path, e);  // left by an interrupted write
      continue;
    }
    if (name.rfind("brinkman-", 0) != 0 || path.extension() != ".bin") continue;
    const auto bytes = fs::file_size(path, e);
    if (e) continue;
    files.push_back({path, time, static_cast<double>(bytes)});
  }
  double total = 0.0;
  for (const Entry& f : files) total += f.bytes;
  std::sort(files.begin(), files.end(), [](const Entry& a, const Entry& b) { return a.time < b.time; });
  std::error_code keep_ec;
  for (const Entry& f : files) {
    if (total <= limit_bytes) break;
    if (fs::equivalent(f.path, keep, keep_ec)) continue;
    std::error_code e;
    if (fs::remove(f.path, e) && !e) {
      total -= f.bytes;
      result.files_removed++;
      result.bytes_removed += f.bytes;
    }
  }
  result.bytes_kept = total;
  return result;
}

bool store_cached_field(const std::filesystem::path& file, const std::string& key,
                        const StaggeredField& field, std::string* error) {
  std::error_code ec;
  std::filesystem::create_directories(file.parent_path(), ec);
  if (ec) {
    if (error) *error = "cannot create cache directory " + file.parent_path().string() + ": " + ec.message();
    return false;
  }
  const std::filesystem::path tmp =
      file.string() + ".tmp." + std::to_string(static_cast<long>(::getpid()));
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) {
      if (error) *error = "cannot write cache file " + tmp.string();
      return false;
    }
    out.write(kMagic, 8);
    write_pod(out, kFormatVersion);
    write_pod(out, static_cast<std::uint32_t>(key.size()));
    out.write(key.data(), static_cast<std::streamsize>(key.size()));
    write_pod(out, static_cast<std::int32_t>(field.grid().nx));
    write_pod(out, static_cast<std::int32_t>(field.grid().ny));
    write_pod(out, field.grid().hx);
    write_pod(out, field.grid().hy);
    write_doubles(out, field.u_ext());
    write_doubles(out, field.v_ext());
    write_doubles(out, field.p_ext());
    write_pod(out, hash_arrays(field));
    if (!out) {
      if (error) *error = "write error on cache file " + tmp.string();
      std::filesystem::remove(tmp, ec);
      return false;
    }
  }
  std::filesystem::rename(tmp, file, ec);
  if (ec) {
    if (error) *error = "cannot rename cache file to " + file.string() + ": " + ec.message();
    std::filesystem::remove(tmp, ec);
    return false;
  }
  return true;
}

}  // namespace hsrod
