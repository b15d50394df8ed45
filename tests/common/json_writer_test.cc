#include "common/json_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace stereonav {
namespace {

TEST(JsonWriterTest, WritesNestedObjectsAndArraysOneMemberPerLine) {
  JsonWriter json;
  json.beginObject()
      .key("frames").value(12)
      .key("coverage").value(0.8765432)
      .key("complete").value(true)
      .key("pose").beginArray().value(1.5).value(-2).endArray()
      .key("events").beginArray().beginObject().key("with").value("static").endObject().endArray()
      .key("empty").beginArray().endArray()
      .key("damage").null()
      .endObject();
  EXPECT_EQ(json.str(),
            "{\n"
            "  \"frames\": 12,\n"
            "  \"coverage\": 0.876543,\n"
            "  \"complete\": true,\n"
            "  \"pose\": [1.5, -2],\n"
            "  \"events\": [{\n"
            "    \"with\": \"static\"\n"
            "  }],\n"
            "  \"empty\": [],\n"
            "  \"damage\": null\n"
            "}\n");
}

TEST(JsonWriterTest, EscapesStringsAndWritesNonFiniteNumbersAsNull) {
  JsonWriter json;
  json.beginArray()
      .value("say \"hi\"\\\n\x01")
      .value(std::numeric_limits<double>::quiet_NaN())
      .value(std::numeric_limits<double>::infinity())
      .value(size_t{7})
      .endArray();
  EXPECT_EQ(json.str(), "[\"say \\\"hi\\\"\\\\\\n\\u0001\", null, null, 7]\n");
}

TEST(JsonWriterTest, MisuseIsALogicError) {
  JsonWriter unbalanced;
  unbalanced.beginObject();
  EXPECT_THROW(unbalanced.str(), std::logic_error);
  EXPECT_THROW(unbalanced.value(1.0), std::logic_error);  // a member needs a key
  EXPECT_THROW(unbalanced.endArray(), std::logic_error);
  JsonWriter in_array;
  in_array.beginArray();
  EXPECT_THROW(in_array.key("x"), std::logic_error);
}

}  // namespace
}  // namespace stereonav
