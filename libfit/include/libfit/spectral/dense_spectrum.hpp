// A spectrum densely sampled on the 1 nm grid (pbrt-v4's DenselySampledSpectrum): one value of T at every integer
// wavelength from first_nm() to last_nm(). The colour pipeline's spectra — colour-matching weights, measured η(λ),
// reflectance at one angle — are values of this type, so that two spectra are combined only on the same grid
// (checked), never aligned by comment.
#pragma once

#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace metalfit {

template <class T>
class DenseSpectrum {
public:
    DenseSpectrum() = default;
    // first_nm..last_nm inclusive, every value `fill`.
    DenseSpectrum(int first_nm, int last_nm, T fill = T{})
        : first_nm_(first_nm), values_(check_grid(first_nm, last_nm), fill) {}

    // The values f(nm) at every nm of the grid.
    template <class F>
    static DenseSpectrum sampled(int first_nm, int last_nm, F&& f) {
        DenseSpectrum s;
        s.first_nm_ = first_nm;
        s.values_.reserve(check_grid(first_nm, last_nm));
        for (int nm = first_nm; nm <= last_nm; ++nm) s.values_.push_back(f(nm));
        return s;
    }

    int first_nm() const { return first_nm_; }
    int last_nm() const { return first_nm_ + static_cast<int>(values_.size()) - 1; }
    std::size_t size() const { return values_.size(); }
    bool empty() const { return values_.empty(); }
    // The wavelength of the i-th value.
    int nm(std::size_t i) const { return first_nm_ + static_cast<int>(i); }

    // The value at an integer wavelength of the grid; throws std::out_of_range off it.
    const T& at_nm(int nm) const { return values_.at(index_of(nm)); }
    T& at_nm(int nm) { return values_.at(index_of(nm)); }
    const T& operator[](std::size_t i) const { return values_[i]; }
    T& operator[](std::size_t i) { return values_[i]; }
    std::span<const T> values() const { return values_; }

    template <class U>
    bool same_grid(const DenseSpectrum<U>& other) const {
        return first_nm() == other.first_nm() && size() == other.size();
    }

    // g(value) at every wavelength, on the same grid.
    template <class G>
    auto map(G&& g) const -> DenseSpectrum<std::decay_t<decltype(g(std::declval<const T&>()))>> {
        using U = std::decay_t<decltype(g(std::declval<const T&>()))>;
        std::size_t i = 0;  // sampled() visits the grid in order: the i-th value is the one at nm(i)
        return DenseSpectrum<U>::sampled(first_nm(), last_nm(), [&](int) { return g(values_[i++]); });
    }

private:
    static std::size_t check_grid(int first_nm, int last_nm) {
        if (last_nm < first_nm)
            throw std::invalid_argument("DenseSpectrum: empty grid " + std::to_string(first_nm) + "–" +
                                        std::to_string(last_nm) + " nm");
        return static_cast<std::size_t>(last_nm - first_nm + 1);
    }
    std::size_t index_of(int nm) const {
        if (nm < first_nm() || nm > last_nm())
            throw std::out_of_range(std::to_string(nm) + " nm is outside the spectrum's " + std::to_string(first_nm()) +
                                    "–" + std::to_string(last_nm()) + " nm");
        return static_cast<std::size_t>(nm - first_nm_);
    }

    int first_nm_ = 0;
    std::vector<T> values_;
};

// Σ_λ a(λ) b(λ) on a shared grid (the CIE's 1 nm summation); throws std::invalid_argument when the grids differ.
template <class A, class B>
auto sum_of_products(const DenseSpectrum<A>& a, const DenseSpectrum<B>& b) {
    if (!a.same_grid(b))
        throw std::invalid_argument("spectra on different grids: " + std::to_string(a.first_nm()) + "–" +
                                    std::to_string(a.last_nm()) + " nm and " + std::to_string(b.first_nm()) + "–" +
                                    std::to_string(b.last_nm()) + " nm");
    decltype(a[0] * b[0]) sum{};
    for (std::size_t i = 0; i < a.size(); ++i) sum += a[i] * b[i];
    return sum;
}

}  // namespace metalfit
