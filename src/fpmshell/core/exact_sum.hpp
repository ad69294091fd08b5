// An exact sum of doubles (a long fixed-point accumulator, Kulisch's idea): every finite double
// is an integer multiple of 2^-1074, so the sum of any number of them is one integer, held here
// in 32-bit digits with room for carries. Its value() is that integer rounded once to the
// nearest double (ties to even): the same bits whatever the order or the grouping of the
// additions. This is what lets sums over parts of a model (chunks, threads, MPI ranks) be
// merged into a total that does not depend on how the model was cut.
#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace fpmshell {

namespace exact_sum_detail {
__extension__ typedef unsigned __int128 Uint128;  // GCC's and Clang's 128-bit integer
}  // namespace exact_sum_detail

class ExactSum {
public:
    /// 32-bit digits from 2^-1074 up: the largest double's top bit is bit 2097 of the grid, a
    /// term spans at most 3 digits from the digit of its lowest bit (53 + 31 bits), and the
    /// last digits take the carries of up to 2^62 terms.
    static constexpr int k_digit_bits = 32;
    static constexpr int k_digits = 69;
    using Digits = std::array<std::int64_t, k_digits>;

    ExactSum() = default;

    /// Adds x exactly. NaN and infinities are kept apart and combine as IEEE addition does
    /// (any NaN, or +inf with -inf, gives NaN): that too is independent of the order.
    void add(double x) {
        const auto bits = std::bit_cast<std::uint64_t>(x);
        const auto exponent = static_cast<int>((bits >> 52) & 0x7ff);
        if (exponent == 0x7ff) {
            special_ += x;  // inf + inf = inf, inf - inf = NaN, NaN + anything = NaN
            has_special_ = true;
            return;
        }
        std::uint64_t mantissa = bits & ((std::uint64_t{1} << 52) - 1);
        if (exponent != 0) mantissa |= std::uint64_t{1} << 52;
        if (mantissa == 0) return;
        // the lowest bit of the mantissa is bit (max(exponent, 1) - 1) of the 2^-1074 grid
        const int position = (exponent == 0 ? 1 : exponent) - 1;
        const int digit = position / k_digit_bits, shift = position % k_digit_bits;
        const Uint128 placed = static_cast<Uint128>(mantissa) << shift;
        const auto d0 = static_cast<std::int64_t>(placed & 0xffffffffu);
        const auto d1 = static_cast<std::int64_t>((placed >> 32) & 0xffffffffu);
        const auto d2 = static_cast<std::int64_t>(placed >> 64);
        const auto ud = static_cast<std::size_t>(digit);
        if (bits >> 63) {
            digits_[ud] -= d0;
            digits_[ud + 1] -= d1;
            digits_[ud + 2] -= d2;
        } else {
            digits_[ud] += d0;
            digits_[ud + 1] += d1;
            digits_[ud + 2] += d2;
        }
        // each digit moves by less than 2^32 per term: carry before an int64 could overflow
        if (++since_carry_ == k_terms_between_carries) carry();
    }

    /// Adds another sum exactly (the merge of two parts).
    void add(const ExactSum& other) {
        ExactSum o = other;
        o.carry();
        carry();
        for (std::size_t i = 0; i < digits_.size(); ++i) digits_[i] += o.digits_[i];
        since_carry_ = 1;  // every digit below 2^33 in magnitude now
        carry();
        if (o.has_special_) {
            special_ += o.special_;
            has_special_ = true;
        }
    }

    /// The sum rounded to the nearest double, ties to even (+-inf past the largest double).
    [[nodiscard]] double value() const {
        if (has_special_) return special_;
        ExactSum s = *this;
        s.carry();
        // carried: digits 0 .. k_digits - 2 in [0, 2^32), the last one signed
        bool negative = s.digits_.back() < 0;
        if (negative) s.negate();
        int top = k_digits - 1;
        while (top >= 0 && s.digits_[static_cast<std::size_t>(top)] == 0) --top;
        if (top < 0) return 0.0;
        // the value is below 2^64 units: at most 2^53 units is exact, a double either way
        if (top <= 1) {
            const std::uint64_t v = (static_cast<std::uint64_t>(s.digits_[1]) << 32) |
                                    static_cast<std::uint64_t>(s.digits_[0]);
            if (v < (std::uint64_t{1} << 53)) {
                const double r = std::ldexp(static_cast<double>(v), -1074);
                return negative ? -r : r;
            }
        }
        // the top 96 bits (three digits) and a sticky bit for everything below them
        const std::size_t t = static_cast<std::size_t>(top);
        Uint128 window = static_cast<Uint128>(s.digits_[t]) << 64;
        if (t >= 1) window |= static_cast<Uint128>(s.digits_[t - 1]) << 32;
        if (t >= 2) window |= static_cast<Uint128>(s.digits_[t - 2]);
        bool sticky = false;
        for (std::size_t i = 0; i + 2 < t; ++i) sticky = sticky || s.digits_[i] != 0;
        const int window_low = (top - 2) * k_digit_bits;  // grid bit of the window's bit 0
        // normalise so that the leading one is bit 63 of `head`, the rest into sticky
        // (drop >= 1: with top >= 2 the window's digit 2 is not zero, with top = 1 the value
        // is at least 2^53 and sits 32 bits up in the window)
        const int drop = 127 - count_leading_zeros(window) - 63;
        const Uint128 mask = (static_cast<Uint128>(1) << drop) - 1;
        sticky = sticky || (window & mask) != 0;
        const auto head = static_cast<std::uint64_t>(window >> drop);
        // round head (64 bits) to 53: 11 bits go
        std::uint64_t mantissa = head >> 11;
        const std::uint64_t rest = head & 0x7ff, half = 0x400;
        if (rest > half || (rest == half && (sticky || (mantissa & 1)))) ++mantissa;
        int exponent = window_low + drop + 11 - 1074;  // of the mantissa's lowest bit
        if (mantissa == (std::uint64_t{1} << 53)) {
            mantissa >>= 1;
            ++exponent;
        }
        const double r = std::ldexp(static_cast<double>(mantissa), exponent);
        return negative ? -r : r;
    }

    /// The digits, carried (for a sum across processes: add the digits of every part, then
    /// from_digits; parts of up to 2^30 each).
    [[nodiscard]] Digits digits() const {
        ExactSum s = *this;
        s.carry();
        return s.digits_;
    }
    /// Whether a NaN or an infinity was added, and their IEEE sum.
    [[nodiscard]] bool has_special() const { return has_special_; }
    [[nodiscard]] double special() const { return special_; }
    /// The sum whose digits are `d` (for example, the digit-wise total of other sums'
    /// digits()), with the IEEE sum `special` of their NaN and infinities if `has_special`.
    [[nodiscard]] static ExactSum from_digits(const Digits& d, bool has_special = false,
                                              double special = 0.0) {
        ExactSum s;
        s.digits_ = d;
        s.since_carry_ = 1;
        s.carry();
        s.has_special_ = has_special;
        s.special_ = special;
        return s;
    }

private:
    using Uint128 = exact_sum_detail::Uint128;
    static constexpr int k_terms_between_carries = 1 << 30;

    /// Moves every digit's overflow into the next: digits 0 .. k_digits - 2 end in
    /// [0, 2^32), the last one holds the sign.
    void carry() {
        if (since_carry_ == 0) return;
        for (std::size_t i = 0; i + 1 < digits_.size(); ++i) {
            const std::int64_t c = digits_[i] >> k_digit_bits;  // floor division by 2^32
            digits_[i] -= c * (std::int64_t{1} << k_digit_bits);
            digits_[i + 1] += c;
        }
        since_carry_ = 0;
    }
    /// -value of a carried sum, carried.
    void negate() {
        for (std::int64_t& d : digits_) d = -d;
        since_carry_ = 1;
        carry();
    }
    [[nodiscard]] static int count_leading_zeros(Uint128 v) {
        const auto hi = static_cast<std::uint64_t>(v >> 64);
        return hi != 0 ? std::countl_zero(hi)
                       : 64 + std::countl_zero(static_cast<std::uint64_t>(v));
    }

    Digits digits_{};
    int since_carry_ = 0;
    bool has_special_ = false;
    double special_ = 0.0;
};

}  // namespace fpmshell
