// On-disk cache of solved background-flow fields, so that a planform is solved
// once and every later run with the same scene loads it instead of solving
// it again (keyed by the scene).
//
// A field is stored in dimensionless form (lengths / H, velocity / U,
// pressure / (mu U / H)). Without the inertia term that field depends only on
// the planform shape in units of H and on the grid, so scenes that differ in
// U, mu, rho or an overall translation share one file; with inertia the key
// also holds Re_H = rho U H / mu. The key is a canonical text of these
// numbers (17 significant digits); the file name is its 64-bit FNV-1a hash,
// and the file repeats the full key, which is compared on loading (a hash
// collision or a stale file is ignored and solved anew).
//
// File format (binary, native endianness, 8-byte doubles):
//   "HSRODBF1"  uint32 format version  uint32 key length  key bytes
//   int32 nx  int32 ny  float64 hx  float64 hy
//   u_ext[(nx+5)(ny+4)]  v_ext[(nx+4)(ny+5)]  p_ext[(nx+2) ny]  (ghost_extension.h)
//   uint64 FNV-1a of all array bytes
// Files are written to a temporary name and renamed, so concurrent runs never
// read a half-written file.
#pragma once

#include "flow/staggered_field.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace hsrod {

// Version of the discretisation; part of every key. Bump it whenever the
// solver's results change so that old cache files are not used.
inline constexpr const char* kBrinkmanSchemeVersion = "mac-shortley-weller-cutflux-2";

// `exponential_wall_layer` (brinkman_grid_solver.h) adds a term to the key;
// keys of the plain scheme are unchanged.
std::string brinkman_cache_key(const ChannelGeometry& scaled_geometry, const MacGrid& grid,
                               double inertia_reynolds, bool exponential_wall_layer = false);
std::uint64_t fnv1a64(const void* data, std::size_t size, std::uint64_t seed = 14695981039346656037ull);
// "brinkman-<16 hex digits>.bin"
std::string brinkman_cache_file_name(const std::string& key);

// $HSROD_CACHE_DIR if set and non-empty, else $XDG_CACHE_HOME/hsrod, else
// $HOME/.cache/hsrod; empty if none of these variables is set.
std::filesystem::path default_cache_directory();

// The field stored in `file` if it exists, is intact and holds `key`. When
// the file exists but is not used, `why_unused` (if given) says why (not an
// hsrod cache file, another format version, another scene - a hash
// collision -, truncated, checksum mismatch); it stays empty for a missing
// file. A field loaded gets its file's modification time set to now, so
// that pruning removes the least recently used files first.
std::optional<StaggeredField> load_cached_field(const std::filesystem::path& file,
                                                const std::string& key,
                                                std::string* why_unused = nullptr);

// Largest total size of the cache files in a directory [bytes]:
// $HSROD_CACHE_MAX_MB (megabytes, > 0) if set, else 2000 MB.
double cache_size_limit_bytes();

// What prune_cache_directory removed.
struct CachePruning {
  int files_removed = 0;
  double bytes_removed = 0.0;  // [bytes]
  double bytes_kept = 0.0;     // cache files left [bytes]
  std::string summary() const;  // "" when nothing was removed
};
// Removes the least recently used brinkman-*.bin files of `dir` until the
// rest totals at most `limit_bytes`, never `keep` (the file just written or
// read); also removes temporary files of interrupted writes older than one
// hour. Errors (a file vanishing under a concurrent run) are ignored.
CachePruning prune_cache_directory(const std::filesystem::path& dir, double limit_bytes,
                                   const std::filesystem::path& keep);
// Writes the field (creating the directory); returns false and sets `error`
// on failure (the solve is still valid, only not cached).
bool store_cached_field(const std::filesystem::path& file, const std::string& key,
                        const StaggeredField& field, std::string* error);

}  // namespace hsrod
