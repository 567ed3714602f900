// Console variables: declaration, typed parsing, set-by priority, ranges, aliases,
// flags, deferred values and change callbacks.

#include "bounce/config/cvar_registry.h"
#include "bounce/core/log.h"

#include <gtest/gtest.h>

namespace bounce {
namespace {

using Status = SetResult::Status;

TEST(CVarRegistry, DeclaresTypedVariablesWithDefaults) {
  CVarRegistry r;
  auto b = r.add<bool>({.name = "t.Bool", .defaultValue = true});
  auto i = r.add<int32_t>({.name = "t.Int", .defaultValue = 128});
  auto f = r.add<float>({.name = "t.Float", .defaultValue = 1.5f});
  auto s = r.add<std::string>({.name = "t.String", .defaultValue = "hello"});
  auto e = r.add<int32_t>({.name = "t.Enum", .defaultValue = 1, .enumNames = {"Off", "Low", "High"}});
  EXPECT_TRUE(b.get());
  EXPECT_EQ(i.get(), 128);
  EXPECT_FLOAT_EQ(f.get(), 1.5f);
  EXPECT_EQ(s.get(), "hello");
  EXPECT_EQ(e->type(), CVarType::Enum);
  EXPECT_EQ(e->getEnumName(), "Low");
  EXPECT_EQ(i->setBy(), SetBy::Constructor);
}

// Found by tests/fuzz/fuzz_cvar.cpp: a string value that starts and ends with a quote, or
// with white space at an end, lost them when printed (as the user ini is written) and
// read back.
TEST(CVarRegistry, StringValuePrintsAsTextThatReadsBackTheSame) {
  CVarRegistry r;
  auto s = r.add<std::string>({.name = "t.String", .defaultValue = "x"});
  for (const std::string value :
       {"\"\"\"", "\"a b\"", "\"\"", "plain", "\"half", " lead", "trail\v", "\x05\"\x05\"\"\v"}) {
    ASSERT_TRUE(r.set(s.cvar(), "\"" + value + "\"", SetBy::Console).ok()) << value;
    ASSERT_EQ(s.get(), value);
    std::string error;
    const std::optional<CVarValue> again = s->parse(s->valueText(), &error);
    ASSERT_TRUE(again) << error;
    EXPECT_EQ(std::get<std::string>(*again), value) << "printed as " << s->valueText();
  }
}

TEST(CVarRegistry, RejectsBadDeclarations) {
  CVarRegistry r;
  r.add<int32_t>({.name = "t.A", .aliases = {"t.AliasA"}});
  EXPECT_THROW(r.add<int32_t>({.name = "T.a"}), std::invalid_argument);       // case-insensitive duplicate
  EXPECT_THROW(r.add<int32_t>({.name = "t.AliasA"}), std::invalid_argument);  // clashes with an alias
  EXPECT_THROW(r.add<int32_t>({.name = "t.B", .defaultValue = 5, .min = 10}), std::invalid_argument);
  EXPECT_THROW(r.add<int32_t>({.name = "t.C", .defaultValue = 3, .allowed = {1, 2}}), std::invalid_argument);
  EXPECT_THROW(r.add<int32_t>({.name = "t.D", .defaultValue = 9, .enumNames = {"A"}}), std::invalid_argument);
  EXPECT_THROW(r.add<int32_t>({.name = ""}), std::invalid_argument);
}

TEST(CVarRegistry, ParsesEachTypeAndRejectsGarbageKeepingTheValue) {
  CVarRegistry r;
  auto b = r.add<bool>({.name = "t.Bool"});
  auto i = r.add<int32_t>({.name = "t.Int", .defaultValue = 4});
  auto f = r.add<float>({.name = "t.Float", .defaultValue = 2.0f});
  auto e = r.add<int32_t>({.name = "t.Enum", .enumNames = {"Off", "Low", "High"}});
  for (const char* yes : {"1", "true", "On", "YES"}) {
    r.set("t.Bool", "0", SetBy::Console);
    EXPECT_EQ(r.set("t.Bool", yes, SetBy::Console).status, Status::Changed) << yes;
    EXPECT_TRUE(b.get());
  }
  EXPECT_EQ(r.set("t.Int", "  +42 ", SetBy::Console).status, Status::Changed);
  EXPECT_EQ(i.get(), 42);
  SetResult bad = r.set("t.Int", "4x", SetBy::Console);
  EXPECT_EQ(bad.status, Status::Rejected);
  EXPECT_NE(bad.message.find("'4x' is not an integer"), std::string::npos) << bad.message;
  EXPECT_NE(bad.message.find("keeps 42"), std::string::npos) << bad.message;
  EXPECT_EQ(i.get(), 42);
  EXPECT_EQ(r.set("t.Float", "1e-3", SetBy::Console).status, Status::Changed);
  EXPECT_FLOAT_EQ(f.get(), 1e-3f);
  EXPECT_EQ(r.set("t.Float", "nan", SetBy::Console).status, Status::Rejected);
  EXPECT_EQ(r.set("t.Float", "inf", SetBy::Console).status, Status::Rejected);
  EXPECT_FLOAT_EQ(f.get(), 1e-3f);
  EXPECT_EQ(r.set("t.Enum", "high", SetBy::Console).status, Status::Changed);
  EXPECT_EQ(e->getEnumName(), "High");
  EXPECT_EQ(r.set("t.Enum", "1", SetBy::Console).status, Status::Changed);
  EXPECT_EQ(e->getEnumName(), "Low");
  EXPECT_EQ(r.set("t.Enum", "3", SetBy::Console).status, Status::Rejected);
  EXPECT_EQ(r.set("t.Enum", "Ultra", SetBy::Console).status, Status::Rejected);
  EXPECT_EQ(e->getEnumName(), "Low");
}

TEST(CVarRegistry, LowerPriorityNeverOverridesHigher) {
  CVarRegistry r;
  auto v = r.add<int32_t>({.name = "t.V", .defaultValue = 1});
  EXPECT_EQ(r.set("t.V", "2", SetBy::BaseIni, "BaseEngine.ini:3").status, Status::Changed);
  EXPECT_EQ(r.set("t.V", "3", SetBy::UserIni, "user.ini:1").status, Status::Changed);
  EXPECT_EQ(r.set("t.V", "4", SetBy::CommandLine, "command line").status, Status::Changed);
  // Everything below the command line is now ignored, whatever the order.
  for (SetBy lower : {SetBy::Constructor, SetBy::BaseIni, SetBy::DefaultIni, SetBy::UserIni}) {
    SetResult res = r.set("t.V", "99", lower, "x.ini:1");
    EXPECT_EQ(res.status, Status::Ignored);
    EXPECT_EQ(v.get(), 4);
  }
  EXPECT_EQ(v->setBy(), SetBy::CommandLine);
  EXPECT_EQ(v->setBySource(), "command line");
  // Same priority: the later write wins.
  EXPECT_EQ(r.set("t.V", "5", SetBy::CommandLine).status, Status::Changed);
  EXPECT_EQ(v.get(), 5);
  // Console beats everything.
  EXPECT_EQ(r.set("t.V", "6", SetBy::Console).status, Status::Changed);
  EXPECT_EQ(r.set("t.V", "7", SetBy::CommandLine).status, Status::Ignored);
  EXPECT_EQ(v.get(), 6);
  EXPECT_EQ(v->setBy(), SetBy::Console);
}

TEST(CVarRegistry, SetByRisesEvenWhenTheValueIsUnchanged) {
  CVarRegistry r;
  auto v = r.add<int32_t>({.name = "t.V", .defaultValue = 1});
  EXPECT_EQ(r.set("t.V", "1", SetBy::CommandLine).status, Status::Unchanged);
  EXPECT_EQ(v->setBy(), SetBy::CommandLine);
  EXPECT_EQ(r.set("t.V", "2", SetBy::UserIni).status, Status::Ignored);
}

TEST(CVarRegistry, RangeRejectsOrClampsAsDeclared) {
  CVarRegistry r;
  auto rej = r.add<int32_t>({.name = "t.Reject", .defaultValue = 128, .min = 32, .max = 256});
  auto cl = r.add<float>(
      {.name = "t.Clamp", .defaultValue = 1.0f, .min = 0.0, .max = 2.0, .outOfRange = RangePolicy::Clamp});
  SetResult a = r.set("t.Reject", "300", SetBy::Console);
  EXPECT_EQ(a.status, Status::Rejected);
  EXPECT_NE(a.message.find("outside [32, 256]"), std::string::npos) << a.message;
  EXPECT_EQ(rej.get(), 128);
  SetResult b = r.set("t.Clamp", "5", SetBy::Console);
  EXPECT_EQ(b.status, Status::Clamped);
  EXPECT_NE(b.message.find("clamped to 2"), std::string::npos) << b.message;
  EXPECT_FLOAT_EQ(cl.get(), 2.0f);
  EXPECT_EQ(r.set("t.Clamp", "-1", SetBy::Console).status, Status::Clamped);
  EXPECT_FLOAT_EQ(cl.get(), 0.0f);
}

TEST(CVarRegistry, AFloatVariableAcceptsItsOwnBoundsWithoutAWarning) {
  // 0.0001 as a float is 9.99999974e-05, below the double 0.0001 of the declaration: the
  // bound itself must still be inside (it read "0.0001 is outside [0.0001, 10000]; clamped").
  CVarRegistry r;
  auto scale = r.add<float>({.name = "t.Scale",
                             .defaultValue = 1.0f,
                             .min = 0.0001,
                             .max = 10000.0,
                             .outOfRange = RangePolicy::Clamp});
  for (const char* text : {"0.0001", "10000"}) {
    SetResult s = r.set("t.Scale", text, SetBy::Console);
    EXPECT_EQ(s.status, Status::Changed) << text << ": " << s.message;
    EXPECT_TRUE(s.message.empty()) << s.message;
  }
  EXPECT_FLOAT_EQ(scale.get(), 10000.0f);
  EXPECT_EQ(r.set("t.Scale", "0.00005", SetBy::Console).status, Status::Clamped);  // still a range
}

TEST(CVarRegistry, AllowedValuesAndCustomValidation) {
  CVarRegistry r;
  auto size =
      r.add<int32_t>({.name = "t.MapSize", .defaultValue = 128, .validate = [](const int32_t& v) {
                        return (v & (v - 1)) == 0 ? std::string() : std::string("must be a power of two");
                      }});
  auto levels = r.add<int32_t>({.name = "t.Levels", .defaultValue = 5, .allowed = {3, 4, 5}});
  SetResult a = r.set("t.MapSize", "100", SetBy::Console);
  EXPECT_EQ(a.status, Status::Rejected);
  EXPECT_NE(a.message.find("power of two"), std::string::npos);
  EXPECT_EQ(size.get(), 128);
  EXPECT_EQ(r.set("t.MapSize", "64", SetBy::Console).status, Status::Changed);
  SetResult b = r.set("t.Levels", "6", SetBy::Console);
  EXPECT_EQ(b.status, Status::Rejected);
  EXPECT_NE(b.message.find("not one of 3, 4, 5"), std::string::npos) << b.message;
  EXPECT_EQ(levels.get(), 5);
}

TEST(CVarRegistry, AliasResolvesToTheSameVariable) {
  CVarRegistry r;
  auto v = r.add<int32_t>({.name = "r.VXGI.DebugMode", .aliases = {"r.VXGIDebugMode"}});
  EXPECT_EQ(r.find("r.VXGIDebugMode"), &v.cvar());
  EXPECT_EQ(r.find("R.VXGIDEBUGMODE"), &v.cvar());
  r.set("r.VXGIDebugMode", "2", SetBy::Console);
  EXPECT_EQ(v.get(), 2);
  r.set("r.vxgi.debugmode", "3", SetBy::Console);
  EXPECT_EQ(v.get(), 3);
}

TEST(CVarRegistry, UnknownNameFromConsoleSuggestsClosest) {
  CVarRegistry r;
  r.add<int32_t>({.name = "r.VXGI.DebugMode"});
  r.add<int32_t>({.name = "r.VXGI.DiffuseCones"});
  SetResult res = r.set("r.VXGI.DebugMod", "1", SetBy::Console);
  EXPECT_EQ(res.status, Status::Rejected);
  EXPECT_NE(res.message.find("'r.VXGI.DebugMode'"), std::string::npos) << res.message;
}

TEST(CVarRegistry, ValuesForUnregisteredVariablesAreHeldAndAppliedInPriorityOrder) {
  CVarRegistry r;
  EXPECT_EQ(r.set("p.Late", "30", SetBy::CommandLine, "command line").status, Status::Deferred);
  EXPECT_EQ(r.set("p.Late", "10", SetBy::BaseIni, "Base.ini:2").status, Status::Deferred);
  EXPECT_EQ(r.setIni("Plug", "LateKey", "20", SetBy::UserIni, "user.ini:4").status, Status::Deferred);
  EXPECT_EQ(r.deferred().size(), 3u);
  auto v = r.add<int32_t>({.name = "p.Late", .ini = {"Plug", "LateKey"}});
  // Applied lowest priority first: the command line wins although it came first.
  EXPECT_EQ(v.get(), 30);
  EXPECT_EQ(v->setBy(), SetBy::CommandLine);
  EXPECT_TRUE(r.deferred().empty());
}

TEST(CVarRegistry, ReadOnlyAcceptsIniButNotConsoleOrCommandLine) {
  CVarRegistry r;
  auto v = r.add<int32_t>({.name = "t.RO", .flags = CVarFlags::ReadOnly});
  EXPECT_EQ(r.set("t.RO", "1", SetBy::DefaultIni).status, Status::Changed);
  EXPECT_EQ(r.set("t.RO", "2", SetBy::CommandLine).status, Status::Rejected);
  SetResult c = r.set("t.RO", "3", SetBy::Console);
  EXPECT_EQ(c.status, Status::Rejected);
  EXPECT_NE(c.message.find("read-only"), std::string::npos);
  EXPECT_EQ(v.get(), 1);
}

TEST(CVarRegistry, CheatVariablesNeedAllowCheats) {
  CVarRegistry r;
  auto allow = r.add<bool>({.name = "con.AllowCheats", .defaultValue = false});
  auto cheat = r.add<int32_t>({.name = "t.Cheat", .flags = CVarFlags::Cheat});
  EXPECT_EQ(r.set("t.Cheat", "1", SetBy::Console).status, Status::Rejected);
  EXPECT_EQ(r.set("t.Cheat", "1", SetBy::UserIni).status, Status::Changed);  // ini files may
  r.set("con.AllowCheats", "1", SetBy::Console);
  EXPECT_EQ(r.set("t.Cheat", "2", SetBy::Console).status, Status::Changed);
  EXPECT_EQ(cheat.get(), 2);
  EXPECT_TRUE(allow.get());
}

TEST(CVarRegistry, RequiresRestartKeepsThePendingValueAfterStartup) {
  CVarRegistry r;
  int changes = 0;
  auto v = r.add<int32_t>({.name = "t.Restart", .defaultValue = 1, .flags = CVarFlags::RequiresRestart});
  Subscription s = v->onChanged([&](const CVar&) { ++changes; });
  EXPECT_EQ(r.set("t.Restart", "2", SetBy::UserIni).status, Status::Changed);  // during start-up
  r.markStartupComplete();
  SetResult p = r.set("t.Restart", "3", SetBy::Console);
  EXPECT_EQ(p.status, Status::Pending);
  EXPECT_EQ(v.get(), 2);
  ASSERT_TRUE(v->pendingValue());
  EXPECT_EQ(std::get<int32_t>(*v->pendingValue()), 3);
  EXPECT_EQ(changes, 1);
}

TEST(CVarRegistry, ChangeCallbacksFireOncePerEffectiveChange) {
  CVarRegistry r;
  auto v = r.add<int32_t>({.name = "t.V", .defaultValue = 1});
  int calls = 0, any = 0;
  Subscription s = v->onChanged([&](const CVar& c) {
    ++calls;
    EXPECT_EQ(c.getInt(), 2);
  });
  Subscription all = r.onAnyChanged([&](const CVar&) { ++any; });
  r.set("t.V", "2", SetBy::Console);
  r.set("t.V", "2", SetBy::Console);  // same value: no callback
  r.set("t.V", "5", SetBy::UserIni);  // ignored: no callback
  r.set("t.V", "x", SetBy::Console);  // rejected: no callback
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(any, 1);
  s.reset();
  all.reset();
  r.set("t.V", "3", SetBy::Console);
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(any, 1);
}

TEST(CVarRegistry, RemovingAnOwnerRemovesItsVariablesAndAliases) {
  CVarRegistry r;
  r.add<int32_t>({.name = "engine.Keep"});
  auto gone = r.add<int32_t>({.name = "plug.Gone", .aliases = {"plug.Old"}, .ini = {"Plug", "Gone"}}, 5);
  Subscription s = gone->onChanged([](const CVar&) {});
  r.removeOwnedBy(5);
  EXPECT_EQ(r.find("plug.Gone"), nullptr);
  EXPECT_EQ(r.find("plug.Old"), nullptr);
  EXPECT_EQ(r.findByIni("Plug", "Gone"), nullptr);
  EXPECT_NE(r.find("engine.Keep"), nullptr);
  s.reset();  // cancelling after the variable is gone is harmless
  // The name is free again.
  EXPECT_NO_THROW(r.add<int32_t>({.name = "plug.Gone"}, 6));
}

TEST(CVarRegistry, IniAndCommandLineFailuresAreLoggedWithTheirSource) {
  CVarRegistry r;
  r.add<int32_t>({.name = "t.V", .defaultValue = 1, .min = 0, .max = 3});
  log::Capture capture;
  r.set("t.V", "9", SetBy::DefaultIni, "config/DefaultEngine.ini:12");
  EXPECT_EQ(capture.count(log::Level::Error, "config/DefaultEngine.ini:12: t.V: 9 is outside [0, 3]"), 1u)
      << capture.joined();
  // Console writes return their message instead of logging it.
  r.set("t.V", "9", SetBy::Console);
  EXPECT_EQ(capture.count(log::Level::Error), 1u);
}

}  // namespace
}  // namespace bounce
