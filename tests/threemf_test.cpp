// The 3MF reader (issue 51): packages made here, each feature against the same mesh written as OBJ, and the
// errors with their part and XML line.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <zlib.h>

#include "model_files.h"
#include "raster/model.h"
#include "raster/raster.h"
#include "support.h"

namespace {

using raster::ModelFormat;

void put(std::string& out, std::uint64_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) out += static_cast<char>(v >> (8 * i) & 0xff);
}

// Raw DEFLATE (no zlib header), as ZIP holds it.
std::string deflate_raw(const std::string& in) {
  z_stream z{};
  deflateInit2(&z, 6, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY);
  std::string out(deflateBound(&z, in.size()), '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));
  z.avail_in = static_cast<uInt>(in.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  deflate(&z, Z_FINISH);
  out.resize(z.total_out);
  deflateEnd(&z);
  return out;
}

struct Entry {
  std::string name, data;
  bool deflated = true;
  std::uint64_t stated_size = 0;  // 0: the data's own size
};

// A ZIP archive of `entries` (the CRC is left 0: the reader does not check it, as the package's XML is
// checked by its parser).
std::string zip(const std::vector<Entry>& entries) {
  std::string out, directory;
  for (const Entry& e : entries) {
    const std::string stored = e.deflated ? deflate_raw(e.data) : e.data;
    const std::uint64_t size = e.stated_size ? e.stated_size : e.data.size();
    const std::size_t local = out.size();
    put(out, 0x04034b50, 4), put(out, 20, 2), put(out, 0, 2), put(out, e.deflated ? 8 : 0, 2);
    put(out, 0, 4), put(out, 0, 4), put(out, stored.size(), 4), put(out, size, 4);
    put(out, e.name.size(), 2), put(out, 0, 2);
    out += e.name + stored;
    put(directory, 0x02014b50, 4), put(directory, 20, 2), put(directory, 20, 2), put(directory, 0, 2);
    put(directory, e.deflated ? 8 : 0, 2), put(directory, 0, 4), put(directory, 0, 4);
    put(directory, stored.size(), 4), put(directory, size, 4), put(directory, e.name.size(), 2);
    put(directory, 0, 2), put(directory, 0, 2), put(directory, 0, 2), put(directory, 0, 2),
        put(directory, 0, 4);
    put(directory, local, 4);
    directory += e.name;
  }
  const std::size_t at = out.size();
  out += directory;
  put(out, 0x06054b50, 4), put(out, 0, 2), put(out, 0, 2), put(out, entries.size(), 2);
  put(out, entries.size(), 2), put(out, directory.size(), 4), put(out, at, 4), put(out, 0, 2);
  return out;
}

const char* kRels =
    R"(<?xml version="1.0" encoding="UTF-8"?>
<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">
<Relationship Target="/3D/3dmodel.model" Id="rel0" Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/>
</Relationships>)";

const std::string kModelOpen =
    R"(<?xml version="1.0" encoding="UTF-8"?>
<model unit="millimeter" xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02")";

// A unit cube's mesh (8 vertices, 12 triangles, counter-clockwise outside) as 3MF and as OBJ.
const double kCube[8][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                            {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
const int kCubeTriangles[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                                   {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};

std::string cube_mesh_xml(const std::string& triangle_extra = "") {
  std::string xml = "<mesh><vertices>\n";
  for (const auto& v : kCube)
    xml += "<vertex x=\"" + test::num(v[0]) + "\" y=\"" + test::num(v[1]) + "\" z=\"" + test::num(v[2]) +
           "\"/>\n";
  xml += "</vertices><triangles>\n";
  for (const auto& t : kCubeTriangles)
    xml += "<triangle v1=\"" + std::to_string(t[0]) + "\" v2=\"" + std::to_string(t[1]) + "\" v3=\"" +
           std::to_string(t[2]) + "\"" + triangle_extra + "/>\n";
  return xml + "</triangles></mesh>";
}

// The cube's OBJ under `place` (a function of a vertex), so a 3MF's placement is checked against it.
template <typename Place>
std::string cube_obj(Place place, int copies = 1) {
  std::string obj;
  for (int c = 0; c < copies; ++c)
    for (const auto& v : kCube) {
      const auto p = place(v, c);
      obj += "v " + test::num(p[0]) + " " + test::num(p[1]) + " " + test::num(p[2]) + "\n";
    }
  for (int c = 0; c < copies; ++c)
    for (const auto& t : kCubeTriangles)
      obj += "f " + std::to_string(t[0] + 1 + 8 * c) + " " + std::to_string(t[1] + 1 + 8 * c) + " " +
             std::to_string(t[2] + 1 + 8 * c) + "\n";
  return obj;
}

std::string package(const std::string& model, std::vector<Entry> more = {}, bool deflated = true) {
  std::vector<Entry> entries = {{"[Content_Types].xml", "<Types/>", deflated},
                                {"_rels/.rels", kRels, deflated},
                                {"3D/3dmodel.model", model, deflated}};
  for (Entry& e : more) entries.push_back(std::move(e));
  return zip(entries);
}

void expect_same_geometry(const raster::Mesh& got, const raster::Mesh& want, const std::string& what) {
  EXPECT_EQ(got.positions, want.positions) << what;
  EXPECT_EQ(got.triangles, want.triangles) << what;
}

raster::Image picture(raster::Mesh mesh) {
  if (mesh.colors.empty()) mesh.colors = {{204, 204, 204, 255}};
  raster::Scene scene = raster::model_scene(std::move(mesh), ModelFormat::threemf);
  scene.width = scene.height = 96;
  return test::render(scene);
}

TEST(ThreeMf, AMeshReadsAsTheSameMeshInObjStoredOrDeflated) {
  const std::string model = kModelOpen + "><resources><object id=\"1\" type=\"model\">" + cube_mesh_xml() +
                            "</object></resources><build><item objectid=\"1\"/></build></model>";
  const raster::Mesh obj = raster::parse_obj(cube_obj([](const double* v, int) {
    return std::array{v[0], v[1], v[2]};
  }));
  for (const bool deflated : {true, false}) {
    const std::string bytes = package(model, {}, deflated);
    EXPECT_EQ(raster::sniff_model(bytes), ModelFormat::threemf);
    const raster::Mesh mesh = raster::parse_3mf(bytes);
    expect_same_geometry(mesh, obj, deflated ? "deflated" : "stored");
    EXPECT_TRUE(mesh.face_colors.empty()) << "no colour given";
    EXPECT_EQ(picture(mesh).pixels, picture(obj).pixels);
  }
  EXPECT_EQ(raster::format_of_file_name("part.3MF"), ModelFormat::threemf);
  EXPECT_EQ(raster::format_of_media_type("model/3mf"), ModelFormat::threemf);
  EXPECT_EQ(raster::model_format(ModelFormat::threemf).up, (raster::Vec3{0, 0, 1})) << "the build platform";
}

TEST(ThreeMf, ComponentsAndItemsArePlacedByTheirTransformsAndAMirrorKeepsTheWinding) {
  // Object 2 holds object 1 twice: as it is, and moved 2 along x; the build places object 2 scaled by 3 and
  // mirrored in y (a negative determinant), then moved up 5.
  const std::string model =
      kModelOpen + "><resources><object id=\"1\">" + cube_mesh_xml() +
      "</object><object id=\"2\"><components><component objectid=\"1\"/>"
      "<component objectid=\"1\" transform=\"1 0 0 0 1 0 0 0 1 2 0 0\"/></components></object></resources>"
      "<build><item objectid=\"2\" transform=\"3 0 0 0 -3 0 0 0 3 0 0 5\"/></build></model>";
  const raster::Mesh mesh = raster::parse_3mf(package(model));
  raster::Mesh obj = raster::parse_obj(cube_obj(
      [](const double* v, int c) {
        return std::array{3 * (v[0] + 2 * c), -3 * v[1], 3 * v[2] + 5};
      },
      2));
  for (auto& t : obj.triangles) std::swap(t[1], t[2]);  // mirrored: the reader flips every triangle back
  expect_same_geometry(mesh, obj, "components");
  // Flipped back means outward: the mesh's signed volume is positive (2 cubes of 27).
  double volume = 0;
  for (const auto& t : mesh.triangles) {
    const raster::Vec3f a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    volume +=
        (a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x)) / 6;
  }
  EXPECT_NEAR(volume, 54, 1e-3);
}

TEST(ThreeMf, TheUnitIsConvertedToMillimetres) {
  const std::string model =
      R"(<model unit="inch" xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02">)"
      "<resources><object id=\"1\">" +
      cube_mesh_xml() + "</object></resources><build><item objectid=\"1\"/></build></model>";
  const raster::Mesh mesh = raster::parse_3mf(package(model));
  ASSERT_EQ(mesh.positions.size(), 8u);
  EXPECT_FLOAT_EQ(mesh.positions[7].x, 25.4f);
  EXPECT_FLOAT_EQ(mesh.positions[7].z, 25.4f);
}

TEST(ThreeMf, BaseMaterialsAndColourGroupsColourTheFaces) {
  const std::string model =
      R"(<model unit="millimeter" xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02")"
      R"( xmlns:m="http://schemas.microsoft.com/3dmanufacturing/material/2015/02" requiredextensions="m">)"
      R"(<resources><basematerials id="5"><base name="red" displaycolor="#FF0000"/><base name="blue" displaycolor="#0000FFFF"/></basematerials>)"
      R"(<m:colorgroup id="6"><m:color color="#00FF0080"/></m:colorgroup>)"
      R"(<object id="1" pid="5" pindex="1">)" +
      cube_mesh_xml() + R"(</object></resources><build><item objectid="1"/></build></model>)";
  // The object's default (blue) everywhere, then the first triangle red and the second green from the group.
  std::string with_faces = model;
  with_faces.replace(with_faces.find("\"/>", with_faces.find("<triangle ")), 3, "\" pid=\"5\" p1=\"0\"/>");
  const std::size_t second = with_faces.find("<triangle ", with_faces.find("<triangle ") + 1);
  with_faces.replace(with_faces.find("\"/>", second), 3, "\" pid=\"6\" p1=\"0\"/>");
  const raster::Mesh mesh = raster::parse_3mf(package(with_faces));
  ASSERT_EQ(mesh.face_colors.size(), 12u);
  EXPECT_EQ(mesh.face_colors[0], (raster::Rgba8{255, 0, 0, 255}));
  EXPECT_EQ(mesh.face_colors[1], (raster::Rgba8{0, 255, 0, 128}));
  for (std::size_t i = 2; i < 12; ++i) EXPECT_EQ(mesh.face_colors[i], (raster::Rgba8{0, 0, 255, 255})) << i;
}

TEST(ThreeMf, ProductionPartsAreFoundInTheirOwnFiles) {
  // As Bambu Studio and Orca write a project: the root model's object holds a component whose mesh is in
  // 3D/Objects/object_1.model (the production extension's p:path).
  const std::string production = "http://schemas.microsoft.com/3dmanufacturing/production/2015/06";
  const std::string root = kModelOpen + " xmlns:p=\"" + production +
                           "\" requiredextensions=\"p\"><resources><object id=\"2\" p:UUID=\"x\"><components>"
                           "<component p:path=\"/3D/Objects/object_1.model\" objectid=\"1\" "
                           "transform=\"1 0 0 0 1 0 0 0 1 0 0 10\"/></components></object></resources>"
                           "<build><item objectid=\"2\"/></build></model>";
  const std::string part = kModelOpen + "><resources><object id=\"1\">" + cube_mesh_xml() +
                           "</object></resources><build/></model>";
  const raster::Mesh mesh = raster::parse_3mf(package(root, {{"3D/Objects/object_1.model", part}}));
  expect_same_geometry(mesh, raster::parse_obj(cube_obj([](const double* v, int) {
                         return std::array{v[0], v[1], v[2] + 10};
                       })),
                       "production part");
  try {
    raster::parse_3mf(package(root));
    ADD_FAILURE() << "a missing part was read";
  } catch (const raster::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("3D/Objects/object_1.model"), std::string::npos) << e.what();
  }
}

std::string error_of(const std::string& bytes) {
  try {
    raster::parse_3mf(bytes);
  } catch (const raster::SceneError& e) {
    EXPECT_EQ(e.kind() == raster::ErrorKind::model || e.kind() == raster::ErrorKind::limit, true);
    return e.what();
  }
  ADD_FAILURE() << "accepted";
  return "";
}

TEST(ThreeMf, ErrorsNameTheirPartAndLine) {
  const std::string unknown = kModelOpen +
                              " xmlns:b=\"http://schemas.microsoft.com/3dmanufacturing/beamlattice/2017/02\" "
                              "requiredextensions=\"b\"><resources/><build/></model>";
  EXPECT_NE(error_of(package(unknown)).find("beamlattice/2017/02"), std::string::npos);
  std::string bad_index = kModelOpen + "><resources><object id=\"1\">" + cube_mesh_xml() +
                          "</object></resources><build><item objectid=\"1\"/></build></model>";
  bad_index.replace(bad_index.find("v1=\"0\""), 6, "v1=\"80\"");
  const std::string message = error_of(package(bad_index));
  // The first triangle is on line 12 (the declaration, <model ...> up to <vertices>, 8 vertices,
  // <triangles>).
  EXPECT_NE(message.find("3MF part 3D/3dmodel.model line 12"), std::string::npos) << message;
  EXPECT_NE(message.find("vertex 80 of 8"), std::string::npos) << message;
  EXPECT_NE(error_of(package(kModelOpen + "><resources/><build><item objectid=\"9\"/></build></model>"))
                .find("no object has the id 9"),
            std::string::npos);
  EXPECT_NE(error_of(package("<!DOCTYPE model [<!ENTITY a \"aaaa\">]>" + kModelOpen + "/>")).find("DOCTYPE"),
            std::string::npos);
  std::string deep = kModelOpen + ">";
  for (int i = 0; i < 100; ++i) deep += "<x>";
  EXPECT_NE(error_of(package(deep)).find("nests elements more than 64 deep"), std::string::npos);
  EXPECT_NE(error_of(package(kModelOpen + "><resources>")).find("not well-formed XML"), std::string::npos);
  EXPECT_NE(error_of(zip({{"x", "y"}})).find("_rels/.rels"), std::string::npos);
  EXPECT_NE(error_of("PK\x03\x04" + std::string(40, ' ')).find("end of central directory"),
            std::string::npos);
}

TEST(ThreeMf, ComponentsThatNameOthersManyTimesAreBounded) {
  // Object k holds object k - 1 twice, 30 levels of empty objects: 2^30 placements were it not bounded.
  std::string resources = "<object id=\"1\"><components/></object>";
  for (int k = 2; k <= 31; ++k)
    resources += "<object id=\"" + std::to_string(k) + "\"><components><component objectid=\"" +
                 std::to_string(k - 1) + "\"/><component objectid=\"" + std::to_string(k - 1) +
                 "\"/></components></object>";
  const std::string model =
      kModelOpen + "><resources>" + resources + "</resources><build><item objectid=\"31\"/></build></model>";
  EXPECT_NE(error_of(package(model)).find("places more than"), std::string::npos);
}

TEST(ThreeMf, AZipBombIsRefusedFromItsDirectory) {
  // A model part that says it inflates to 100 GB from a few bytes: refused before anything is inflated (no
  // 100 GB is asked of anyone), and so is one within DEFLATE's ratio that is over the entry limit.
  const std::string bomb =
      zip({{"_rels/.rels", kRels}, {"3D/3dmodel.model", "<model/>", true, 100'000'000'000ull}});
  EXPECT_NE(error_of(bomb).find("more than DEFLATE can"), std::string::npos);
  std::string noise(1'600'000, '\0');  // incompressible: its DEFLATE is as large, so 1.5 GB is within 1032:1
  std::uint32_t x = 12345;
  for (char& c : noise) x = x * 1664525u + 1013904223u, c = static_cast<char>(x >> 24);
  const std::string large =
      zip({{"_rels/.rels", kRels}, {"3D/3dmodel.model", noise, true, 1'500'000'000ull}});
  EXPECT_NE(error_of(large).find("over the limit"), std::string::npos);
  // And an entry that inflates to more than it says is refused too.
  const std::string liar =
      zip({{"_rels/.rels", kRels}, {"3D/3dmodel.model", std::string(5000, ' ') + "<model/>", true, 100}});
  EXPECT_NE(error_of(liar).find("more than its stated 100 bytes"), std::string::npos);
}

}  // namespace
