// A stand-in for xdg-desktop-portal's file chooser on a private session bus, for the studio
// panel's tests: it owns org.freedesktop.portal.Desktop, answers OpenFile and SaveFile with a
// Request at the path the specification gives (sender and handle_token), and later sends that
// Request's Response as the file `answer` says at the time: "uri <URI>" (chosen), "cancel" (the
// person cancelled), "fail" (ended some other way), "nothing" (success without a file) or "never"
// (the dialog stays open until closed). Each call, and each Close of
// a Request, is written as a line to `log`. Prints "ready" once the name is its own.
//
// Usage: fake_portal ANSWER_FILE LOG_FILE
#include <gio/gio.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace {

const char* const kInterfaces = R"(<node>
  <interface name="org.freedesktop.portal.FileChooser">
    <method name="OpenFile">
      <arg type="s" direction="in"/><arg type="s" direction="in"/>
      <arg type="a{sv}" direction="in"/><arg type="o" direction="out"/>
    </method>
    <method name="SaveFile">
      <arg type="s" direction="in"/><arg type="s" direction="in"/>
      <arg type="a{sv}" direction="in"/><arg type="o" direction="out"/>
    </method>
    <property name="version" type="u" access="read"/>
  </interface>
  <interface name="org.freedesktop.portal.Request">
    <method name="Close"/>
  </interface>
</node>)";

std::string answerFile, logFile;
GDBusNodeInfo* interfaces = nullptr;

void log(const std::string& line) {
  std::ofstream(logFile, std::ios::app) << line << "\n";
}

std::string option(GVariant* options, const char* key) {
  GVariant* value = g_variant_lookup_value(options, key, nullptr);
  if (!value) return "-";
  std::string text;
  if (g_variant_is_of_type(value, G_VARIANT_TYPE_STRING))
    text = g_variant_get_string(value, nullptr);
  else if (g_variant_is_of_type(value, G_VARIANT_TYPE_BYTESTRING))
    text = g_variant_get_bytestring(value);
  else
    text = g_variant_get_type_string(value);
  g_variant_unref(value);
  return text;
}

struct Pending {
  GDBusConnection* bus;
  std::string sender, path;
  guint object;
};

void onRequestCall(GDBusConnection*, const gchar*, const gchar* path, const gchar*,
                   const gchar* method, GVariant*, GDBusMethodInvocation* invocation,
                   gpointer data) {
  auto* pending = static_cast<Pending*>(data);
  if (std::string(method) == "Close") {
    log("Close " + std::string(path));
    g_dbus_connection_unregister_object(pending->bus, pending->object);
  }
  g_dbus_method_invocation_return_value(invocation, nullptr);
}

const GDBusInterfaceVTable kRequestCalls = {onRequestCall, nullptr, nullptr, {}};

gboolean respond(gpointer data) {
  auto* pending = static_cast<Pending*>(data);
  std::ifstream in(answerFile);
  std::string kind, uri;
  in >> kind >> uri;
  GVariantBuilder results;
  g_variant_builder_init(&results, G_VARIANT_TYPE_VARDICT);
  guint32 response = 1;
  if (kind == "never") return G_SOURCE_REMOVE;
  if (kind == "fail") response = 2;     // "the user interaction was ended in some other way"
  if (kind == "nothing") response = 0;  // chosen, yet no uris
  if (kind == "uri") {
    response = 0;
    const gchar* uris[] = {uri.c_str(), nullptr};
    g_variant_builder_add(&results, "{sv}", "uris", g_variant_new_strv(uris, 1));
  }
  g_dbus_connection_emit_signal(pending->bus, pending->sender.c_str(), pending->path.c_str(),
                                "org.freedesktop.portal.Request", "Response",
                                g_variant_new("(ua{sv})", response, &results), nullptr);
  g_dbus_connection_unregister_object(pending->bus, pending->object);
  return G_SOURCE_REMOVE;
}

void onChooserCall(GDBusConnection* bus, const gchar* sender, const gchar*, const gchar*,
                   const gchar* method, GVariant* parameters, GDBusMethodInvocation* invocation,
                   gpointer) {
  const gchar *parent = nullptr, *title = nullptr;
  GVariant* options = nullptr;
  g_variant_get(parameters, "(&s&s@a{sv})", &parent, &title, &options);
  const std::string token = option(options, "handle_token");
  std::string unique = sender + 1;  // without its ':'
  for (char& c : unique)
    if (c == '.') c = '_';
  auto* pending = new Pending{bus, sender,
                              "/org/freedesktop/portal/desktop/request/" + unique + "/" + token, 0};
  std::ostringstream line;
  line << method << " title=" << title << " token=" << token
       << " current_folder=" << option(options, "current_folder")
       << " current_name=" << option(options, "current_name")
       << " filters=" << option(options, "filters");
  log(line.str());
  g_variant_unref(options);
  pending->object =
      g_dbus_connection_register_object(bus, pending->path.c_str(), interfaces->interfaces[1],
                                        &kRequestCalls, pending, nullptr, nullptr);
  g_dbus_method_invocation_return_value(invocation, g_variant_new("(o)", pending->path.c_str()));
  g_timeout_add(50, respond, pending);
}

GVariant* onChooserProperty(GDBusConnection*, const gchar*, const gchar*, const gchar*,
                            const gchar*, GError**, gpointer) {
  return g_variant_new_uint32(4);
}

const GDBusInterfaceVTable kChooserCalls = {onChooserCall, onChooserProperty, nullptr, {}};

void onNameAcquired(GDBusConnection*, const gchar*, gpointer) {
  std::printf("ready\n");
  std::fflush(stdout);
}

void onNameLost(GDBusConnection*, const gchar*, gpointer loop) {
  g_main_loop_quit(static_cast<GMainLoop*>(loop));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: fake_portal ANSWER_FILE LOG_FILE\n");
    return 2;
  }
  answerFile = argv[1];
  logFile = argv[2];
  interfaces = g_dbus_node_info_new_for_xml(kInterfaces, nullptr);
  GDBusConnection* bus = g_bus_get_sync(G_BUS_TYPE_SESSION, nullptr, nullptr);
  if (!bus) return 1;
  g_dbus_connection_register_object(bus, "/org/freedesktop/portal/desktop",
                                    interfaces->interfaces[0], &kChooserCalls, nullptr, nullptr,
                                    nullptr);
  GMainLoop* loop = g_main_loop_new(nullptr, FALSE);
  g_bus_own_name_on_connection(bus, "org.freedesktop.portal.Desktop", G_BUS_NAME_OWNER_FLAGS_NONE,
                               onNameAcquired, onNameLost, loop, nullptr);
  g_main_loop_run(loop);  // until the bus goes (the test ends it)
  return 0;
}
