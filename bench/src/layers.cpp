#include "metalfit_bench/layers.hpp"

#include <memory>
#include <stdexcept>

#include "libfit/base/quadrature.hpp"
#include "libfit/fit/fit.hpp"
#include "libfit/io/layer_materials.hpp"
#include "libfit/io/layer_stack.hpp"

namespace metalfit::bench {

LayersBench layers_bench(const Environment& env, const std::string& material_id, const TimingOptions& timing,
                         const std::string& model) {
    const Material bare = load_material(env.catalog, material_id);
    const FilmCatalog films = FilmCatalog::load(env.catalog.data_dir());
    // The stacks, loaded as --coat 1.5 and --film TiO2:80nm load them.
    struct Case {
        std::string id;
        Material material;
    };
    std::vector<Case> cases{{"bare", bare}};
    const auto add = [&](const std::string& id, bool coat, bool film) {
        auto stack = std::make_shared<LayerStack>();
        if (coat) stack->coat = load_coat(films, "1.5");
        if (film) stack->film = load_film(films, "TiO2:80nm");
        Material m = bare;
        m.layers = std::move(stack);
        cases.push_back({id, std::move(m)});
    };
    add("coat", true, false);
    add("film", false, true);
    add("coat+film", true, true);

    const MaterialFitRequest request{env.spectral, env.error, parse_model_list(model)};
    std::vector<double> nodes;
    for (const QuadratureNode& q : gauss_legendre_unit(env.error.nodes)) nodes.push_back(q.mu);
    std::vector<TimedJob> jobs;
    for (const Case& c : cases) {
        jobs.push_back({[&env, &c, &nodes] {
                            const ReferenceCurve curve(c.material, env.colorimetry, env.converter, env.spectral);
                            const std::vector<RGB> values = curve(nodes);
                            if (values.empty()) throw std::logic_error("no nodes");
                        },
                        1.0});
        jobs.push_back({[&env, &c, &request] {
                            const MaterialFit fit = fit_material(c.material, env.colorimetry, env.converter, request);
                            if (fit.models.empty()) throw std::logic_error("no fit");
                        },
                        1.0});
    }
    const std::vector<JobTiming> t = time_interleaved(jobs, timing);
    LayersBench out{bare.id, model, {}};
    for (std::size_t i = 0; i < cases.size(); ++i)
        out.rows.push_back({cases[i].id, describe_stack(cases[i].material), 1e-6 * t[2 * i].median_ns,
                            ratio(t[2 * i], t[0]), 1e-6 * t[2 * i + 1].median_ns, ratio(t[2 * i + 1], t[1])});
    return out;
}

}  // namespace metalfit::bench
