// Stagecraft's world driver for Player (docs/debugging-robots.md, "The frozen world").
//
// A Player plugin driver that Stagecraft adds to the copy of a Robot Session's .cfg. It provides one
// simulation device on a port of its own (so robot programs never see it in their device lists) and
// answers two property requests there:
//
//   SET_PROPERTY prop "frozen" value "1"  stop the Stage world this Player runs; "0" lets it run on
//   GET_PROPERTY prop "frozen"            the state
//   SET_PROPERTY prop "window" value "raise"  brings Stage's window to the front (and out of the dock), for
//                                         the IDE's "Show Stage's Window": another process cannot raise it
//
// Each is answered with the same request as ACK, its value the text
// "<frozen 0|1> <simulated time, microseconds> <gui|headless>", or with a NACK when this Player runs
// no Stage world. The driver is not threaded: Player calls it from its main loop, the thread Stage's
// own plugin updates the world on, so the world is only ever touched between two of its updates.
//
// How the world stops: with a window (usegui 1) Stage is driven by FLTK timeouts, and World::Stop()
// removes them (as Stage's own pause does); then Player's main loop would sleep in Fl::wait() until the
// next window event, so while frozen this driver keeps a short FLTK timeout of its own that lets Player
// go on serving its clients. Without a window Stage's plugin calls World::Update() on every pass of the
// main loop, which ignores the pause flag; a quit request makes it return before it advances anything,
// and cancelling the request lets it run on. A world the user had paused already stays paused.
//
// Stagecraft's own code, built against the installed Player and Stage; nothing of theirs is changed.

#include <dlfcn.h>
#include <link.h>

#include <cstdio>
#include <cstring>
#include <string>

#include <FL/Fl.H>
#include <FL/Fl_Window.H>
#include <libplayercore/playercore.h>
#include <stage.hh>

namespace {

// StgDriver::world, the world Stage's Player plugin (stageplugin.so) runs, a public static member.
const char *const WORLD_SYMBOL = "_ZN9StgDriver5worldE";
// While frozen with a window: how often Player's main loop wakes to serve its clients.
const double SERVE_INTERVAL_S = 0.01;

int findStagePlugin(struct dl_phdr_info *info, size_t, void *found) {
  const char *name = info->dlpi_name;
  if (name != NULL && strstr(name, "stageplugin") != NULL) {
    *static_cast<std::string *>(found) = name;
    return 1;
  }
  return 0;
}

// Player loads plugins with local symbols, so the Stage plugin is looked up among the loaded objects.
Stg::World *stageWorld() {
  void *symbol = dlsym(RTLD_DEFAULT, WORLD_SYMBOL);
  if (symbol == NULL) {
    std::string path;
    dl_iterate_phdr(findStagePlugin, &path);
    if (path.empty())
      return NULL;
    void *handle = dlopen(path.c_str(), RTLD_LAZY | RTLD_NOLOAD);
    if (handle == NULL)
      return NULL;
    symbol = dlsym(handle, WORLD_SYMBOL);
    dlclose(handle);
  }
  return symbol == NULL ? NULL : *static_cast<Stg::World **>(symbol);
}

void keepPlayerServing(void *) { Fl::repeat_timeout(SERVE_INTERVAL_S, keepPlayerServing); }

} // namespace

class StagecraftWorld : public Driver {
public:
  StagecraftWorld(ConfigFile *cf, int section)
      : Driver(cf, section, false, PLAYER_MSGQUEUE_DEFAULT_MAXLEN, PLAYER_SIMULATION_CODE), frozen(false),
        leftPaused(false), frozenWorld(NULL) {}

  virtual int Shutdown() {
    thaw();
    return 0;
  }

  virtual int ProcessMessage(QueuePointer &resp, player_msghdr *hdr, void *data) {
    const bool set = Message::MatchMessage(hdr, PLAYER_MSGTYPE_REQ, PLAYER_SIMULATION_REQ_SET_PROPERTY, device_addr);
    const bool get = Message::MatchMessage(hdr, PLAYER_MSGTYPE_REQ, PLAYER_SIMULATION_REQ_GET_PROPERTY, device_addr);
    if (!set && !get)
      return -1;
    player_simulation_property_req_t *req = static_cast<player_simulation_property_req_t *>(data);
    const std::string prop = req->prop == NULL ? "" : std::string(req->prop, strnlen(req->prop, req->prop_count));
    const bool window = set && prop == "window";
    if (prop != "frozen" && !window)
      return -1;
    Stg::World *world = stageWorld();
    if (world == NULL) {
      PLAYER_ERROR("stagecraft_world: this Player runs no Stage world (no stage driver in its .cfg?)");
      return -1; // Player answers with a NACK
    }
    if (window) {
      // FLTK's show() of a window on screen maps and raises it (XMapRaised): the window comes to the front
      Fl_Window *w = world->IsGUI() ? Fl::first_window() : NULL;
      if (w != NULL)
        w->show();
    } else if (set) {
      const bool on = req->value != NULL && req->value_count > 0 && req->value[0] == '1';
      if (on)
        freeze(world);
      else
        thaw();
    }
    char text[96];
    snprintf(text, sizeof text, "%d %llu %s", frozen ? 1 : 0, (unsigned long long)world->SimTimeNow(),
             world->IsGUI() ? "gui" : "headless");
    player_simulation_property_req_t reply = *req;
    reply.value = text;
    reply.value_count = strlen(text) + 1;
    Publish(device_addr, resp, PLAYER_MSGTYPE_RESP_ACK, hdr->subtype, &reply, sizeof reply, NULL);
    return 0;
  }

private:
  void freeze(Stg::World *world) {
    if (frozen)
      return;
    frozenWorld = world;
    if (world->IsGUI()) {
      leftPaused = world->Paused();
      if (!leftPaused)
        world->Stop();
      Fl::add_timeout(SERVE_INTERVAL_S, keepPlayerServing);
    } else {
      leftPaused = world->TestQuit();
      world->Quit();
    }
    frozen = true;
  }

  void thaw() {
    if (!frozen)
      return;
    Stg::World *world = frozenWorld;
    if (world->IsGUI()) {
      Fl::remove_timeout(keepPlayerServing);
      if (!leftPaused)
        world->Start();
    } else if (!leftPaused) {
      world->CancelQuit();
    }
    frozen = false;
  }

  bool frozen;
  bool leftPaused;
  Stg::World *frozenWorld;
};

static Driver *StagecraftWorldInit(ConfigFile *cf, int section) { return new StagecraftWorld(cf, section); }

extern "C" {
int player_driver_init(DriverTable *table) {
  table->AddDriver("stagecraft_world", StagecraftWorldInit);
  return 0;
}
}
