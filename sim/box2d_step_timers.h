// Box2D's step timers, which plantsim turns off. b2World::Step times its phases for
// b2World::GetProfile with about ten gettimeofday calls a step: 64 % of a bare Box2D step on
// world_N200 and 7 % of a sensing episode on this machine (docs/config.md), for a profile
// nothing here reads. plantsim defines b2Timer's three members itself; Debian's libbox2d calls
// them through its procedure linkage table, so the program's definitions take their place
// (ELF symbol interposition), and the physics is unchanged: the timers only fill the profile.
#pragma once

namespace plantsim::sim {

/// Off by default. On, the timers measure as Box2D's own do (gettimeofday), so that `bench sim`
/// can time bare Box2D as Debian ships it.
void set_box2d_step_timers(bool on);
bool box2d_step_timers();

}  // namespace plantsim::sim
