// The pass graph without GL: fake passes and a fake resource type that logs its creation and destruction, so that
// culling, order, lifetimes and the errors are checked against what actually ran.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "glpreview/graph/pass_graph.hpp"
#include "test_support.hpp"

namespace metalfit::glpreview::graph {
namespace test_preview_graph {

std::vector<std::string> events;  // "run A", "create t", "free t", in the order they happened

// A resource the graph creates from a descriptor (as it creates a cube map) and that logs its lifetime.
struct FakeTexture {
    struct Descriptor {
        std::string name;
        int size = 0;
    };
    static FakeTexture create(const Descriptor& d) { return FakeTexture(d); }
    explicit FakeTexture(const Descriptor& d) : name(d.name), size(d.size) { events.push_back("create " + name); }
    FakeTexture(FakeTexture&& o) noexcept : name(std::move(o.name)), size(o.size) { o.name.clear(); }
    FakeTexture& operator=(FakeTexture&&) = delete;
    ~FakeTexture() {
        if (!name.empty()) events.push_back("free " + name);
    }
    std::string name;
    int size;
};

struct Single {
    Handle<int> out;
};
struct Texture {
    Handle<FakeTexture> texture;
};
struct Nothing {};

// A producer of an int, a consumer that writes a file, and a pass nobody reads.
TEST(PreviewGraph, CullsPassesNobodyReadsAndRunsTheRestInOrder) {
    events.clear();
    PassGraph g;
    const auto& a = g.add_pass<Single>(
        {"A", "makes 1", Processor::cpu}, [](Builder& b, Single& d) { d.out = b.produce<int>("one"); },
        [](const Single& d, Resources& r) {
            events.push_back("run A");
            r.emplace(d.out, 1);
        });
    g.add_pass<Single>(
        {"unused", "makes 2", Processor::gpu}, [](Builder& b, Single& d) { d.out = b.produce<int>("two"); },
        [](const Single&, Resources&) { events.push_back("run unused"); });
    int seen = 0;
    g.add_pass<Nothing>(
        {"write", "file", Processor::cpu},
        [&](Builder& b, Nothing&) {
            b.read(a.out);
            b.write_file("one.txt");
        },
        [&, h = a.out](const Nothing&, Resources& r) {
            events.push_back("run write");
            seen = r.get(h);
        });
    g.compile();
    EXPECT_TRUE(g.runs("A"));
    EXPECT_FALSE(g.runs("unused"));
    ASSERT_EQ(g.skipped().size(), 1u);
    EXPECT_EQ(g.skipped()[0].why, "culled: nothing asked for reads two");
    EXPECT_EQ(g.output_files(), std::vector<std::string>{"one.txt"});
    g.execute();
    EXPECT_EQ(events, (std::vector<std::string>{"run A", "run write"}));
    EXPECT_EQ(seen, 1);
}

// Passes declared out of order run in dependency order; independent passes keep their declaration order.
TEST(PreviewGraph, OrdersTopologically) {
    events.clear();
    PassGraph g;
    const Handle<int> late = g.declare<int>("late");
    auto log = [](std::string name) { return [name](const Nothing&, Resources&) { events.push_back(name); }; };
    g.add_pass<Nothing>(
        {"consumer", "", Processor::cpu},
        [&](Builder& b, Nothing&) {
            b.read(late);
            b.write_file("out");
        },
        log("consumer"));
    g.add_pass<Nothing>(
        {"independent", "", Processor::cpu}, [&](Builder& b, Nothing&) { b.write_file("other"); }, log("independent"));
    g.add_pass<Nothing>(
        {"producer", "", Processor::cpu}, [&](Builder& b, Nothing&) { b.write(late); }, log("producer"));
    g.compile();
    ASSERT_EQ(g.passes().size(), 3u);
    EXPECT_EQ(g.passes()[0].name, "independent");
    EXPECT_EQ(g.passes()[1].name, "producer");
    EXPECT_EQ(g.passes()[2].name, "consumer");
    EXPECT_EQ(g.passes()[2].reads, std::vector<std::string>{"late"});
    g.execute();
    EXPECT_EQ(events, (std::vector<std::string>{"independent", "producer", "consumer"}));
}

// A resource with a descriptor is created just before its first user runs and freed just after its last user;
// a requested one survives the graph.
TEST(PreviewGraph, CreatesAtFirstUseAndFreesAfterLastUse) {
    events.clear();
    {
        PassGraph g;
        const auto& made = g.add_pass<Texture>(
            {"make", "", Processor::gpu},
            [](Builder& b, Texture& d) {
                d.texture = b.create<FakeTexture>("cube", {"cube", 8});
            },
            [](const Texture& d, Resources& r) {
                events.push_back("run make, size " + std::to_string(r.get(d.texture).size));
            });
        const auto& kept = g.add_pass<Texture>(
            {"reader", "", Processor::gpu},
            [&](Builder& b, Texture& d) {
                b.read(made.texture);
                d.texture = b.create<FakeTexture>("kept", {"kept", 2});
            },
            [](const Texture&, Resources&) { events.push_back("run reader"); });
        g.add_pass<Nothing>(
            {"last reader", "", Processor::cpu},
            [&](Builder& b, Nothing&) {
                b.read(made.texture);
                b.write_file("f");
            },
            [](const Nothing&, Resources&) { events.push_back("run last reader"); });
        g.request(kept.texture);
        g.compile();
        ASSERT_EQ(g.lifetimes().size(), 3u);  // cube, kept, file:f
        EXPECT_EQ(g.lifetimes()[0].resource, "cube");
        EXPECT_EQ(g.lifetimes()[0].first, 0u);
        EXPECT_EQ(g.lifetimes()[0].last, 2u);
        EXPECT_EQ(g.lifetimes()[1].first, 1u);
        EXPECT_EQ(g.lifetimes()[1].last, 1u);
        g.execute();
        EXPECT_EQ(events, (std::vector<std::string>{"create cube", "run make, size 8", "create kept", "run reader",
                                                    "run last reader", "free cube"}));
        ASSERT_NE(g.result(kept.texture), nullptr);
        EXPECT_EQ(g.result(kept.texture)->size, 2);
    }
    EXPECT_EQ(events.back(), "free kept");  // the requested resource lives as long as the graph
}

TEST(PreviewGraph, CycleIsAnErrorNamingThePasses) {
    PassGraph g;
    const Handle<int> x = g.declare<int>("x");
    const auto& a = g.add_pass<Single>(
        {"A", "", Processor::cpu},
        [&](Builder& b, Single& d) {
            b.read(x);
            d.out = b.produce<int>("a");
        },
        [](const Single&, Resources&) {});
    g.add_pass<Nothing>(
        {"B", "", Processor::cpu},
        [&](Builder& b, Nothing&) {
            b.read(a.out);
            b.write(x);
            b.write_file("out");
        },
        [](const Nothing&, Resources&) {});
    try {
        g.compile();
        FAIL() << "no error";
    } catch (const GraphError& e) {
        EXPECT_EQ(std::string(e.what()), "the passes A, B depend on each other in a cycle");
    }
}

TEST(PreviewGraph, ReadOfANeverWrittenResourceIsAnError) {
    PassGraph g;
    const Handle<int> orphan = g.declare<int>("orphan");
    const Handle<int> imported = g.import <int>("scene", 3);
    g.add_pass<Nothing>(
        {"reader", "", Processor::cpu},
        [&](Builder& b, Nothing&) {
            b.read(imported);  // imports need no writer
            b.read(orphan);
            b.write_file("out");
        },
        [](const Nothing&, Resources&) {});
    try {
        g.compile();
        FAIL() << "no error";
    } catch (const GraphError& e) {
        EXPECT_EQ(std::string(e.what()), "pass 'reader' reads 'orphan', which no pass writes and nobody imported");
    }
}

TEST(PreviewGraph, TwoWritersAndUndeclaredAccessAreErrors) {
    PassGraph g;
    const auto& a = g.add_pass<Single>(
        {"A", "", Processor::cpu}, [](Builder& b, Single& d) { d.out = b.produce<int>("v"); },
        [](const Single&, Resources&) {});
    EXPECT_THROW(g.add_pass<Nothing>(
                     {"B", "", Processor::cpu}, [&](Builder& b, Nothing&) { b.write(a.out); },
                     [](const Nothing&, Resources&) {}),
                 GraphError);
    PassGraph h;
    const auto& p = h.add_pass<Single>(
        {"P", "", Processor::cpu}, [](Builder& b, Single& d) { d.out = b.produce<int>("v"); },
        [](const Single& d, Resources& r) { r.emplace(d.out, 5); });
    h.add_pass<Nothing>(
        {"sneaky", "", Processor::cpu}, [](Builder& b, Nothing&) { b.write_file("out"); },
        [h_out = p.out](const Nothing&, Resources& r) { r.get(h_out); });
    h.compile();
    try {
        h.execute();
        FAIL() << "no error";
    } catch (const GraphError& e) {
        EXPECT_EQ(std::string(e.what()), "pass 'sneaky' uses 'v' without declaring it in its setup");
    }
}

}  // namespace test_preview_graph
}  // namespace metalfit::glpreview::graph
