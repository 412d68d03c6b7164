// Owning, move-only handles of every OpenGL object glpreview makes: the name is deleted when the handle dies.
// No glGen*/glCreate*/glDelete* call exists outside this header (and link_program, which makes shaders through it).
#pragma once

#include <utility>

#include "glpreview/gl/gl.hpp"

namespace metalfit::glpreview::gl {

// One GL name and the function that deletes it; moved-from handles hold 0 and delete nothing.
template <void (*Delete)(GLuint)>
class Object {
public:
    Object() = default;
    explicit Object(GLuint id) : id_(id) {}
    Object(Object&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
    Object& operator=(Object&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0);
        }
        return *this;
    }
    Object(const Object&) = delete;
    Object& operator=(const Object&) = delete;
    ~Object() { reset(); }

    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset() {
        if (id_) Delete(id_);
        id_ = 0;
    }

private:
    GLuint id_ = 0;
};

namespace detail {
inline void delete_texture(GLuint id) { glDeleteTextures(1, &id); }
inline void delete_framebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
inline void delete_renderbuffer(GLuint id) { glDeleteRenderbuffers(1, &id); }
inline void delete_buffer(GLuint id) { glDeleteBuffers(1, &id); }
inline void delete_vertex_array(GLuint id) { glDeleteVertexArrays(1, &id); }
inline void delete_query(GLuint id) { glDeleteQueries(1, &id); }
inline void delete_program(GLuint id) { glDeleteProgram(id); }
inline void delete_shader(GLuint id) { glDeleteShader(id); }
}  // namespace detail

using Texture = Object<detail::delete_texture>;
using Framebuffer = Object<detail::delete_framebuffer>;
using Renderbuffer = Object<detail::delete_renderbuffer>;
using Buffer = Object<detail::delete_buffer>;
using VertexArray = Object<detail::delete_vertex_array>;
using Query = Object<detail::delete_query>;
using Program = Object<detail::delete_program>;
using Shader = Object<detail::delete_shader>;

namespace detail {
// A new object from one of GL 4.5's glCreate*(…, 1, &id) calls, owned by its handle.
template <class Handle, class Create>
Handle create_one(Create&& create) {
    GLuint id = 0;
    create(&id);
    return Handle(id);
}
}  // namespace detail

inline Texture create_texture(GLenum target) {
    return detail::create_one<Texture>([&](GLuint* id) { glCreateTextures(target, 1, id); });
}
inline Framebuffer create_framebuffer() {
    return detail::create_one<Framebuffer>([](GLuint* id) { glCreateFramebuffers(1, id); });
}
inline Renderbuffer create_renderbuffer() {
    return detail::create_one<Renderbuffer>([](GLuint* id) { glCreateRenderbuffers(1, id); });
}
inline Buffer create_buffer() {
    return detail::create_one<Buffer>([](GLuint* id) { glCreateBuffers(1, id); });
}
inline VertexArray create_vertex_array() {
    return detail::create_one<VertexArray>([](GLuint* id) { glCreateVertexArrays(1, id); });
}
inline Query create_query(GLenum target) {
    return detail::create_one<Query>([&](GLuint* id) { glCreateQueries(target, 1, id); });
}
inline Program create_program() { return Program(glCreateProgram()); }
inline Shader create_shader(GLenum type) { return Shader(glCreateShader(type)); }

}  // namespace metalfit::glpreview::gl
