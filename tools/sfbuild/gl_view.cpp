#include "tools/sfbuild/gl_view.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "scenefile/mesh.h"
#include "tools/sfbuild/gl_program.h"

namespace sfbuild {
namespace {

constexpr double kNear = 0.05;
constexpr double kFar = 5000.0;
constexpr int kSegments = 64;
constexpr int kGridHalfLines = 10;
// The lights the preview shades with (the shader's kMaxLights); sfrender
// uses them all.
constexpr std::size_t kMaxLights = 16;

const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 mvp;
uniform mat4 model;
uniform mat3 normalMatrix;
out vec3 worldNormal;
out vec3 worldPosition;
void main() {
  worldNormal = normalMatrix * normal;
  worldPosition = vec3(model * vec4(position, 1.0));
  gl_Position = mvp * vec4(position, 1.0);
}
)";

// The scene's own lights, Phong as RENDERING.md writes it (ambient per
// light, the normal turned toward the eye), without shadows, reflection or
// refraction: what sfrender draws at --depth 0 where nothing is in shadow.
// A scene with no light would be black, as sfrender draws it; so that
// shapes can still be placed, the builder then lights it with a fixed key
// and fill light (`lightCount` 0). The selection gets an orange tint and
// rim along its outline.
const char* kFragmentShader = R"(#version 330 core
const int kMaxLights = 16;
in vec3 worldNormal;
in vec3 worldPosition;
uniform vec3 colour;
uniform int lit;
uniform int highlight;
uniform vec3 eye;
uniform int lightCount;
uniform vec3 lightPositions[kMaxLights];
uniform vec3 lightColours[kMaxLights];
uniform vec4 material;  // AMBIENT, DIFFUSE, SPECULAR, SHININESS
out vec4 fragment;
void main() {
  if (lit == 0) {
    fragment = vec4(colour, 1.0);
    return;
  }
  vec3 n = normalize(worldNormal);
  vec3 v = normalize(eye - worldPosition);
  if (dot(n, v) < 0.0) n = -n;
  vec3 shaded = vec3(0.0);
  if (lightCount == 0) {
    float key = max(dot(n, normalize(vec3(0.5, 1.0, 0.7))), 0.0);
    float fill = max(dot(n, normalize(vec3(-0.7, 0.3, 0.4))), 0.0);
    shaded = colour * (0.2 + 0.65 * key + 0.25 * fill);
  }
  for (int i = 0; i < lightCount; ++i) {
    vec3 l = normalize(lightPositions[i] - worldPosition);
    vec3 light = lightColours[i];
    shaded += colour * light * material.x;
    float cosine = dot(l, n);
    if (cosine > 0.0) {
      shaded += colour * light * material.y * cosine;
      shaded += light * material.z * pow(max(0.0, dot(reflect(-l, n), v)), material.w);
    }
  }
  if (highlight != 0) {
    vec3 orange = vec3(1.0, 0.6, 0.1);
    float rim = 1.0 - abs(dot(n, v));
    shaded = mix(shaded, orange, 0.1) + orange * pow(rim, 4.0);
  }
  fragment = vec4(clamp(shaded, 0.0, 1.0), 1.0);
}
)";

glm::mat4 toFloat(const glm::dmat4& m) {
  return glm::mat4(m);
}

}  // namespace

GlView::GlView() {
  program_ = linkGlProgram(kVertexShader, kFragmentShader, "the view's");
  mvpLocation_ = glGetUniformLocation(program_, "mvp");
  modelLocation_ = glGetUniformLocation(program_, "model");
  highlightLocation_ = glGetUniformLocation(program_, "highlight");
  eyeLocation_ = glGetUniformLocation(program_, "eye");
  normalLocation_ = glGetUniformLocation(program_, "normalMatrix");
  colourLocation_ = glGetUniformLocation(program_, "colour");
  litLocation_ = glGetUniformLocation(program_, "lit");
  lightCountLocation_ = glGetUniformLocation(program_, "lightCount");
  lightPositionsLocation_ = glGetUniformLocation(program_, "lightPositions");
  lightColoursLocation_ = glGetUniformLocation(program_, "lightColours");
  materialLocation_ = glGetUniformLocation(program_, "material");

  for (scene::ObjectKind kind : scene::kObjectKinds) {
    meshes_[static_cast<std::size_t>(kind)] =
        upload(scene::primitiveMesh(kind, kSegments, kPlaneHalfSize));
  }
  // The grid: lines on y = 0, drawn as a mesh of line pairs.
  scene::TriangleMesh grid;
  for (int i = -kGridHalfLines; i <= kGridHalfLines; ++i) {
    float a = static_cast<float>(i), h = static_cast<float>(kGridHalfLines);
    for (glm::vec3 p :
         {glm::vec3(a, 0, -h), glm::vec3(a, 0, h), glm::vec3(-h, 0, a), glm::vec3(h, 0, a)}) {
      grid.indices.push_back(static_cast<std::uint32_t>(grid.positions.size()));
      grid.positions.push_back(p);
      grid.normals.push_back({0, 1, 0});
    }
  }
  grid_ = upload(grid);
}

GlView::~GlView() {
  for (Mesh& m : meshes_) {
    glDeleteVertexArrays(1, &m.vao);
    glDeleteBuffers(1, &m.vbo);
    glDeleteBuffers(1, &m.ebo);
  }
  glDeleteVertexArrays(1, &grid_.vao);
  glDeleteBuffers(1, &grid_.vbo);
  glDeleteBuffers(1, &grid_.ebo);
  glDeleteProgram(program_);
}

GlView::Mesh GlView::upload(const scene::TriangleMesh& mesh) {
  Mesh m;
  std::vector<float> interleaved;
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    for (int c = 0; c < 3; ++c) interleaved.push_back(mesh.positions[i][c]);
    for (int c = 0; c < 3; ++c) interleaved.push_back(mesh.normals[i][c]);
  }
  glGenVertexArrays(1, &m.vao);
  glBindVertexArray(m.vao);
  glGenBuffers(1, &m.vbo);
  glBindBuffer(GL_ARRAY_BUFFER, m.vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(interleaved.size() * sizeof(float)),
               interleaved.data(), GL_STATIC_DRAW);
  glGenBuffers(1, &m.ebo);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m.ebo);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER,
               static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
               mesh.indices.data(), GL_STATIC_DRAW);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float), nullptr);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 6 * sizeof(float),
                        reinterpret_cast<const void*>(3 * sizeof(float)));
  glEnableVertexAttribArray(1);
  glBindVertexArray(0);
  m.count = static_cast<GLsizei>(mesh.indices.size());
  return m;
}

void GlView::draw(const BuilderState& state) {
  glViewport(0, 0, state.width, state.height);
  glDisable(GL_DITHER);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  if (state.idView) {
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  } else {
    glClearColor(0.16f, 0.17f, 0.19f, 1.0f);
  }
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glUseProgram(program_);

  glm::dmat4 viewProjection = projectionMatrix(state, kNear, kFar) * viewMatrix(state);
  auto drawMesh = [&](const Mesh& mesh, const glm::dmat4& model, const glm::vec3& colour, bool lit,
                      GLenum primitive, bool highlight = false) {
    glm::mat4 mvp = toFloat(viewProjection * model);
    glm::mat4 modelFloat = toFloat(model);
    glUniformMatrix4fv(modelLocation_, 1, GL_FALSE, glm::value_ptr(modelFloat));
    glUniform1i(highlightLocation_, highlight ? 1 : 0);
    glm::mat3 normal = glm::mat3(glm::inverseTranspose(glm::dmat3(model)));
    glUniformMatrix4fv(mvpLocation_, 1, GL_FALSE, glm::value_ptr(mvp));
    glUniformMatrix3fv(normalLocation_, 1, GL_FALSE, glm::value_ptr(normal));
    glUniform3fv(colourLocation_, 1, glm::value_ptr(colour));
    glUniform1i(litLocation_, lit ? 1 : 0);
    glBindVertexArray(mesh.vao);
    glDrawElements(primitive, mesh.count, GL_UNSIGNED_INT, nullptr);
  };

  const auto& objects = state.scene.objects;
  if (state.idView) {
    for (std::size_t i = 0; i < objects.size(); ++i) {
      glm::vec3 colour = glm::vec3(idColour(i)) / 255.0f;
      drawMesh(meshes_[static_cast<std::size_t>(objects[i].kind)], objects[i].matrix, colour, false,
               GL_TRIANGLES);
    }
    glBindVertexArray(0);
    return;
  }

  glm::vec3 eye = glm::vec3(state.scene.camera.matrix[3]);
  glUniform3fv(eyeLocation_, 1, glm::value_ptr(eye));
  std::vector<glm::vec3> lightPositions, lightColours;
  for (const scene::Light& light : state.scene.lights) {
    if (lightPositions.size() == kMaxLights) break;
    lightPositions.push_back(glm::vec3(light.position()));
    lightColours.push_back(glm::vec3(light.colour));
  }
  auto lightCount = static_cast<GLsizei>(lightPositions.size());
  glUniform1i(lightCountLocation_, lightCount);
  if (lightCount > 0) {
    glUniform3fv(lightPositionsLocation_, lightCount, glm::value_ptr(lightPositions[0]));
    glUniform3fv(lightColoursLocation_, lightCount, glm::value_ptr(lightColours[0]));
  }
  auto setMaterial = [&](const scene::Material& m) {
    glUniform4f(materialLocation_, static_cast<float>(m.ambient), static_cast<float>(m.diffuse),
                static_cast<float>(m.specular), static_cast<float>(m.shininess));
  };
  auto selected = [&](bool light, std::size_t index) {
    return state.selection && state.selection->light == light && state.selection->index == index;
  };
  // Filled surfaces sit a little back, so that the grid drawn on them wins
  // the depth test.
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.0f, 1.0f);
  for (std::size_t i = 0; i < objects.size(); ++i) {
    setMaterial(objects[i].material);
    drawMesh(meshes_[static_cast<std::size_t>(objects[i].kind)], objects[i].matrix,
             glm::vec3(objects[i].material.colour), true, GL_TRIANGLES, selected(false, i));
  }
  // The lights' markers are lit flat: a light is not lit by itself.
  glUniform1i(lightCountLocation_, 0);
  for (std::size_t i = 0; i < state.scene.lights.size(); ++i) {
    glm::dmat4 model = glm::scale(glm::translate(glm::dmat4(1.0), state.scene.lights[i].position()),
                                  glm::dvec3(kLightRadius));
    drawMesh(meshes_[static_cast<std::size_t>(scene::ObjectKind::Sphere)], model,
             glm::vec3(1.0f, 0.9f, 0.1f), true, GL_TRIANGLES, selected(true, i));
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
  drawMesh(grid_, glm::dmat4(1.0), glm::vec3(0.42f, 0.43f, 0.46f), false, GL_LINES);
  glBindVertexArray(0);
}

}  // namespace sfbuild
