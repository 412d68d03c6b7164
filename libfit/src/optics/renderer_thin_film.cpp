// Renderers' thin-film approximations (renderer_thin_film.hpp). The MaterialX functions follow MaterialX 1.39.4's
// libraries/pbrlib/genglsl/lib/mx_microfacet_specular.glsl line by line (names kept), in double.
#include "libfit/optics/renderer_thin_film.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace metalfit {
namespace {

constexpr double kPi = std::numbers::pi;

double square(double x) { return x * x; }

std::array<double, 3> times(const XyzToRgbMatrix& m, const std::array<double, 3>& xyz) {
    std::array<double, 3> rgb{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) rgb[i] += m[i][j] * xyz[j];
    return rgb;
}
std::array<double, 3> to_cie_rgb(const std::array<double, 3>& xyz) { return times(kXyzToCie1931Rgb, xyz); }

// mx_fresnel_dielectric_polarized(cosTheta, ior): (Rp, Rs).
std::array<double, 2> mx_fresnel_dielectric_polarized(double cos_theta, double ior) {
    const double cos2 = square(std::clamp(cos_theta, 0.0, 1.0)), sin2 = 1.0 - cos2;
    const double t0 = std::max(ior * ior - sin2, 0.0), t1 = t0 + cos2, t2 = 2.0 * std::sqrt(t0) * cos_theta;
    const double rs = (t1 - t2) / (t1 + t2);
    const double t3 = cos2 * t0 + sin2 * sin2, t4 = t2 * sin2;
    return {rs * (t3 - t4) / (t3 + t4), rs};
}

// mx_fresnel_conductor_polarized(cosTheta, n, k, Rp, Rs), one channel.
void mx_fresnel_conductor_polarized(double cos_theta, double n, double k, double& rp, double& rs) {
    const double cos2 = square(std::clamp(cos_theta, 0.0, 1.0)), sin2 = 1.0 - cos2;
    const double n2 = n * n, k2 = k * k;
    const double t0 = n2 - k2 - sin2, a2plusb2 = std::sqrt(t0 * t0 + 4.0 * n2 * k2), t1 = a2plusb2 + cos2;
    const double a = std::sqrt(std::max(0.5 * (a2plusb2 + t0), 0.0)), t2 = 2.0 * a * cos_theta;
    rs = (t1 - t2) / (t1 + t2);
    const double t3 = cos2 * a2plusb2 + sin2 * sin2, t4 = t2 * sin2;
    rp = rs * (t3 - t4) / (t3 + t4);
}

// mx_fresnel_conductor_phase_polarized(cosTheta, eta1, eta2, kappa2, phiP, phiS), one channel.
void mx_fresnel_conductor_phase_polarized(double cos_theta, double eta1, double eta2, double kappa2, double& phi_p,
                                          double& phi_s) {
    const double k2 = kappa2 / eta2, sin2 = 1.0 - cos_theta * cos_theta;
    const double A = eta2 * eta2 * (1.0 - k2 * k2) - eta1 * eta1 * sin2;
    const double B = std::sqrt(A * A + square(2.0 * eta2 * eta2 * k2));
    const double U = std::sqrt((A + B) / 2.0), V = std::max(0.0, std::sqrt((B - A) / 2.0));
    phi_s = std::atan2(2.0 * eta1 * V * cos_theta, U * U + V * V - square(eta1 * cos_theta));
    phi_p = std::atan2(2.0 * eta1 * eta2 * eta2 * cos_theta * (2.0 * k2 * U - (1.0 - k2 * k2) * V),
                       square(eta2 * eta2 * (1.0 + k2 * k2) * cos_theta) - eta1 * eta1 * (U * U + V * V));
}

double smoothstep(double edge0, double edge1, double x) {
    const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

}  // namespace

std::array<double, 3> thin_film_sensitivity(double opd_m, const std::array<double, 3>& shift) {
    const double phase = 2.0 * kPi * opd_m;
    constexpr double val[3] = {5.4856e-13, 4.4201e-13, 5.2481e-13};
    constexpr double pos[3] = {1.6810e+06, 1.7953e+06, 2.2084e+06};
    constexpr double var[3] = {4.3278e+09, 9.3046e+09, 6.6121e+09};
    std::array<double, 3> xyz{};
    for (int i = 0; i < 3; ++i)
        xyz[i] = val[i] * std::sqrt(2.0 * kPi * var[i]) * std::cos(pos[i] * phase + shift[i]) *
                 std::exp(-var[i] * phase * phase);
    xyz[0] += 9.7470e-14 * std::sqrt(2.0 * kPi * 4.5282e+09) * std::cos(2.2399e+06 * phase + shift[0]) *
              std::exp(-4.5282e+09 * phase * phase);
    for (double& v : xyz) v /= 1.0685e-7;
    return xyz;
}

ChannelReflectance materialx_thin_film(double mu, const ChannelIndices& metal, double film_ior, double thickness_nm) {
    ChannelReflectance out{};
    if (!(thickness_nm > 0.0)) {  // FresnelData.airy = tf_thickness > 0.0: mx_fresnel_conductor
        for (int c = 0; c < 3; ++c) {
            double rp = 0, rs = 0;
            mx_fresnel_conductor_polarized(mu, metal[c].real(), metal[c].imag(), rp, rs);
            out[c] = 0.5 * (rp + rs);
        }
        return out;
    }
    const double cos_theta = mu, eta1 = 1.0, eta2 = std::max(film_ior, eta1);
    const double cos_theta_t = std::sqrt(1.0 - (1.0 - square(cos_theta)) * square(eta1 / eta2));
    std::array<double, 2> R12 = mx_fresnel_dielectric_polarized(cos_theta, eta2 / eta1);  // (p, s)
    if (cos_theta_t <= 0.0) R12 = {1.0, 1.0};
    const std::array<double, 2> T121{1.0 - R12[0], 1.0 - R12[1]};
    std::array<double, 3> R23p{}, R23s{}, phi23p{}, phi23s{};
    for (int c = 0; c < 3; ++c) {
        const double eta3 = metal[c].real(), kappa3 = metal[c].imag();
        mx_fresnel_conductor_polarized(cos_theta_t, eta3 / eta2, kappa3 / eta2, R23p[c], R23s[c]);
        mx_fresnel_conductor_phase_polarized(cos_theta_t, eta2, eta3, kappa3, phi23p[c], phi23s[c]);
    }
    const double cos_b = std::cos(std::atan(eta2 / eta1));
    const std::array<double, 2> phi21{cos_theta < cos_b ? 0.0 : kPi, kPi};
    const double opd = 2.0 * eta2 * cos_theta_t * (thickness_nm * 1.0e-9);
    std::array<double, 3> I{};
    // One polarisation: p (index 0) with R23p, phi23p; s (index 1) with R23s, phi23s.
    const auto polarisation = [&](int pol, const std::array<double, 3>& R23, const std::array<double, 3>& phi23) {
        std::array<double, 3> r123{}, Rs{}, Cm{}, shift{};
        for (int c = 0; c < 3; ++c) {
            r123[c] = std::max(std::sqrt(R12[pol] * R23[c]), 0.0);
            Rs[c] = square(T121[pol]) * R23[c] / (1.0 - R12[pol] * R23[c]);
            I[c] += R12[pol] + Rs[c];
            Cm[c] = Rs[c] - T121[pol];
        }
        for (int m = 1; m <= 2; ++m) {
            for (int c = 0; c < 3; ++c) {
                Cm[c] *= r123[c];
                shift[c] = m * (phi23[c] + phi21[pol]);
            }
            const std::array<double, 3> S = thin_film_sensitivity(m * opd, shift);
            for (int c = 0; c < 3; ++c) I[c] += Cm[c] * 2.0 * S[c];
        }
    };
    polarisation(0, R23p, phi23p);
    polarisation(1, R23s, phi23s);
    for (double& v : I) v *= 0.5;
    const std::array<double, 3> rgb = to_cie_rgb(I);
    for (int c = 0; c < 3; ++c) out[c] = std::clamp(rgb[c], 0.0, 1.0);
    return out;
}

ChannelReflectance belcour_barla_thin_film(double mu, const ChannelIndices& metal, double film_ior,
                                           double thickness_nm) {
    return belcour_barla_thin_film(mu, metal, film_ior, thickness_nm, kXyzToCie1931Rgb);
}

ChannelReflectance belcour_barla_thin_film(double mu, const ChannelIndices& metal, double film_ior, double thickness_nm,
                                           const XyzToRgbMatrix& xyz_to_rgb) {
    using C = std::complex<double>;
    using stack_detail::normal_component;
    using stack_detail::quotient_or_zero;
    mu = std::clamp(mu, 0.0, 1.0);
    const double mu2 = mu * mu;
    // The authors' code: the film's index goes from the ambient's to its own over 0–0.03 µm, so that a vanishing
    // film is the bare metal.
    const double n_f = 1.0 + (film_ior - 1.0) * smoothstep(0.0, 0.03, thickness_nm * 1e-3), n_f2 = n_f * n_f;
    const C u0(mu, 0), u_f = normal_component(C(n_f, 0), mu2);
    const C r01[2] = {quotient_or_zero(u0 - u_f, u0 + u_f), quotient_or_zero(n_f2 * u0 - u_f, n_f2 * u0 + u_f)};
    const double opd = 2.0 * thickness_nm * 1e-9 * u_f.real();  // 2 n_f d cos θ_f
    const std::array<double, 3> S0 = thin_film_sensitivity(0.0, {0.0, 0.0, 0.0});
    ChannelReflectance out{};
    for (int c = 0; c < 3; ++c) {
        const C eta_m = metal[c], eta_m2 = eta_m * eta_m, u_m = normal_component(eta_m, mu2);
        const C r12[2] = {quotient_or_zero(u_f - u_m, u_f + u_m),
                          quotient_or_zero(eta_m2 * u_f - n_f2 * u_m, eta_m2 * u_f + n_f2 * u_m)};
        std::array<double, 3> xyz{};
        for (int pol = 0; pol < 2; ++pol) {
            const double R12 = std::clamp(std::norm(r01[pol]), 0.0, 1.0), T121 = 1.0 - R12;
            const double R23 = std::clamp(std::norm(r12[pol]), 0.0, 1.0);
            // Phase of one round trip besides the path: reflection film → air (r10 = −r01) and film → metal.
            const double phi2 = std::arg(-r01[pol]) + std::arg(r12[pol]);
            const double Rs = T121 * T121 * R23 / (1.0 - R12 * R23), r123 = std::sqrt(R12 * R23);
            for (int i = 0; i < 3; ++i) xyz[i] += 0.5 * (R12 + Rs) * S0[i];
            double Cm = Rs - T121;
            for (int m = 1; m <= 3; ++m) {
                Cm *= r123;
                const std::array<double, 3> S = thin_film_sensitivity(m * opd, {m * phi2, m * phi2, m * phi2});
                for (int i = 0; i < 3; ++i) xyz[i] += 0.5 * Cm * 2.0 * S[i];
            }
        }
        out[c] = std::clamp(times(xyz_to_rgb, xyz)[c], 0.0, 1.0);
    }
    return out;
}

ChannelReflectance three_wavelength_airy(double mu, const std::array<StackOptics<double>, 3>& optics) {
    ChannelReflectance out{};
    for (int c = 0; c < 3; ++c) out[c] = stack_reflectance_unpolarized(mu, optics[c]);
    return out;
}

}  // namespace metalfit
