#include "libfit/base/file_digest.hpp"

#include <openssl/crypto.h>
#include <openssl/evp.h>

#include <array>
#include <fstream>
#include <memory>

#include "libfit/base/errors.hpp"

namespace metalfit {

namespace {

using Context = std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)>;

// SHA-256, fetched once per process. OpenSSL's default start-up reads openssl.cnf and registers the name of every
// legacy cipher and digest, which the default provider's name map then walks: 5 M instructions, a twentieth of
// `metalfit fit Au` (docs/fitting.md). A SHA-256 digest needs none of it (the same digest either way).
const EVP_MD* sha256_method() {
    static const EVP_MD* const md = [] {
        OPENSSL_init_crypto(
            OPENSSL_INIT_NO_LOAD_CONFIG | OPENSSL_INIT_NO_ADD_ALL_CIPHERS | OPENSSL_INIT_NO_ADD_ALL_DIGESTS, nullptr);
        return EVP_MD_fetch(nullptr, "SHA256", nullptr);
    }();
    return md;
}

Context sha256_context() {
    Context ctx(EVP_MD_CTX_new(), EVP_MD_CTX_free);
    const EVP_MD* md = sha256_method();
    if (!ctx || md == nullptr || EVP_DigestInit_ex(ctx.get(), md, nullptr) != 1)
        throw std::runtime_error("OpenSSL: cannot initialise SHA-256");
    return ctx;
}

std::string hex_digest(const Context& ctx) {
    std::array<unsigned char, EVP_MAX_MD_SIZE> digest{};
    unsigned int length = 0;
    EVP_DigestFinal_ex(ctx.get(), digest.data(), &length);
    static constexpr char hex[] = "0123456789abcdef";
    std::string out;
    for (unsigned int i = 0; i < length; ++i) {
        out += hex[digest[i] >> 4];
        out += hex[digest[i] & 15];
    }
    return out;
}

}  // namespace

std::string sha256_file(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError({file}, "cannot open file");
    const Context ctx = sha256_context();
    std::array<char, 1 << 16> buffer{};
    while (in.read(buffer.data(), buffer.size()) || in.gcount() > 0) {
        EVP_DigestUpdate(ctx.get(), buffer.data(), static_cast<std::size_t>(in.gcount()));
        if (in.eof()) break;
    }
    return hex_digest(ctx);
}

std::string sha256_bytes(std::string_view bytes) {
    const Context ctx = sha256_context();
    EVP_DigestUpdate(ctx.get(), bytes.data(), bytes.size());
    return hex_digest(ctx);
}

}  // namespace metalfit
