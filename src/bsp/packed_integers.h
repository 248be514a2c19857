// SPDX-License-Identifier: LGPL-3.0-or-later
// Four GMP integers in one allocation, read through GMP's read-only views (mpz_roinit_n): the
// exact kernel's memoised point values (X, Y, Z, W) and triangle planes (n, d). Four
// mpz_class cost four 16-byte headers and four heap blocks, each with malloc's header and
// rounding and often a limb or two more than the value needs (GMP sizes a product's result
// for the largest possible value). The 300k-triangle assembly keeps 183,000 values and 98,000
// planes for the whole build (heaptrack: 67 of its 158 MB peak heap); packed (24 bytes and one
// block of exactly the limbs in use), the 1M-triangle assembly's peak RSS drops by a fifth. GMP
// offers no packed multi-integer type; this is the small amount of code its documented low-level
// interface (mpz_limbs_read, mpz_roinit_n) needs. Internal to the exact kernel
// (geometry_exact.cpp).
#pragma once
#include <gmpxx.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>

namespace exbsp::detail {

/// Read-only views of four integers; valid while what they view lives and is unchanged.
struct integer_views {
  std::array<__mpz_struct, 4> z;
  mpz_srcptr operator[](int k) const { return &z[static_cast<std::size_t>(k)]; }
};

/// Views of four mpz_class (no copy of their limbs).
inline integer_views views_of(const mpz_class& a, const mpz_class& b, const mpz_class& c,
                              const mpz_class& d) {
  return {{*a.get_mpz_t(), *b.get_mpz_t(), *c.get_mpz_t(), *d.get_mpz_t()}};
}

class packed_integers {
 public:
  packed_integers() = default;
  /// Copies the four integers' limbs into one block of exactly their total size.
  explicit packed_integers(const integer_views& v) {
    std::size_t total = 0;
    for (int k = 0; k < 4; ++k) {
      const std::size_t n = mpz_size(v[k]);
      size_[static_cast<std::size_t>(k)] = static_cast<std::int32_t>(
          mpz_sgn(v[k]) < 0 ? -static_cast<long>(n) : static_cast<long>(n));
      total += n;
    }
    limbs_.reset(new mp_limb_t[total == 0 ? 1 : total]);
    mp_limb_t* at = limbs_.get();
    for (int k = 0; k < 4; ++k) {
      const std::size_t n = mpz_size(v[k]);
      if (n != 0) std::memcpy(at, mpz_limbs_read(v[k]), n * sizeof(mp_limb_t));
      at += n;
    }
  }
  /// The four integers, viewed in place.
  integer_views views() const {
    integer_views v;
    const mp_limb_t* at = limbs_.get();
    for (std::size_t k = 0; k < 4; ++k) {
      mpz_roinit_n(&v.z[k], at, size_[k]);
      at += std::abs(size_[k]);
    }
    return v;
  }
  /// Bytes of the limb block (without the allocator's own header).
  std::size_t limb_bytes() const {
    std::size_t n = 0;
    for (std::int32_t s : size_) n += static_cast<std::size_t>(std::abs(s));
    return n * sizeof(mp_limb_t);
  }

 private:
  std::unique_ptr<mp_limb_t[]> limbs_;
  std::array<std::int32_t, 4> size_{};  ///< limbs per integer, negative for a negative one
};

}  // namespace exbsp::detail
