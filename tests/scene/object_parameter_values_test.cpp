#include "bounce/scene/object_parameters.h"

#include <gtest/gtest.h>

namespace bounce {
namespace {

TEST(ObjectParameterValues, SetThenFindByExactName) {
  ObjectParameterValues values;
  EXPECT_EQ(values.find("UsedWithVxgiVoxelization"), nullptr);
  values.set("UsedWithVxgiVoxelization", true);
  values.set("Samples", int32_t(4));
  const ObjectParameterValue* v = values.find("UsedWithVxgiVoxelization");
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(std::get<bool>(*v), true);
  EXPECT_EQ(std::get<int32_t>(*values.find("Samples")), 4);
  EXPECT_EQ(values.find("usedwithvxgivoxelization"), nullptr);  // names compare exactly
}

TEST(ObjectParameterValues, SetReplacesAnExistingValue) {
  ObjectParameterValues values;
  values.set("Scale", 1.0f);
  values.set("Scale", 2.5f);
  EXPECT_EQ(values.entries().size(), 1u);
  EXPECT_FLOAT_EQ(std::get<float>(*values.find("Scale")), 2.5f);
}

TEST(ObjectParameterValues, EraseRemovesOnlyTheNamedValue) {
  ObjectParameterValues values;
  values.set("A", true);
  values.set("B", false);
  EXPECT_TRUE(values.erase("A"));
  EXPECT_FALSE(values.erase("A"));
  EXPECT_EQ(values.find("A"), nullptr);
  EXPECT_NE(values.find("B"), nullptr);
}

TEST(ObjectParameterValues, KindNames) {
  EXPECT_EQ(objectKindName(ObjectKind::Material), "Material");
  EXPECT_EQ(objectKindName(ObjectKind::Light), "Light");
}

}  // namespace
}  // namespace bounce
