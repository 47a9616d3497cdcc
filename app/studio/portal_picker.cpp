// The XDG desktop portal's file chooser: org.freedesktop.portal.FileChooser, as
// https://flatpak.github.io/xdg-desktop-portal/docs/doc-org.freedesktop.portal.FileChooser.html
// describes it. OpenFile or SaveFile returns a Request object at once; the dialog's outcome comes
// later as that Request's Response signal, subscribed to before the call so none is missed.
#include <gio/gio.h>
#include <glib-unix.h>
#include <sys/stat.h>

#include <unistd.h>
#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

#include "app/studio/portal_picker.hpp"
#include "app/studio/zenity_picker.hpp"

namespace curvefold::studio {

namespace {

constexpr const char* kPortal = "org.freedesktop.portal.Desktop";
constexpr const char* kPortalPath = "/org/freedesktop/portal/desktop";
constexpr const char* kFileChooser = "org.freedesktop.portal.FileChooser";
constexpr const char* kRequest = "org.freedesktop.portal.Request";
// A bus that does not answer a question within this is not used: frames wait on find().
constexpr int kFindTimeoutMs = 500;

struct Unref {
  void operator()(gpointer object) const { g_object_unref(object); }
};
using Connection = std::unique_ptr<GDBusConnection, Unref>;

struct FreeError {
  void operator()(GError* error) const { g_error_free(error); }
};
using Error = std::unique_ptr<GError, FreeError>;

struct UnrefVariant {
  void operator()(GVariant* value) const { g_variant_unref(value); }
};
using Variant = std::unique_ptr<GVariant, UnrefVariant>;

// The session bus's address, without starting one (GLib would fall back to dbus-launch).
std::string sessionBusAddress() {
  if (const char* address = std::getenv("DBUS_SESSION_BUS_ADDRESS"); address && *address)
    return address;
  if (const char* runtime = std::getenv("XDG_RUNTIME_DIR"); runtime && *runtime) {
    const std::string socket = std::string(runtime) + "/bus";
    struct stat info {};
    if (::stat(socket.c_str(), &info) == 0 && S_ISSOCK(info.st_mode)) {
      gchar* escaped = g_dbus_address_escape_value(socket.c_str());
      std::string address = std::string("unix:path=") + escaped;
      g_free(escaped);
      return address;
    }
  }
  return "";
}

// A connection of its own (not GLib's shared one, which ends the process when the bus goes away).
Connection openBus(const std::string& address, std::string& failure) {
  GError* error = nullptr;
  GDBusConnection* connection = g_dbus_connection_new_for_address_sync(
      address.c_str(),
      GDBusConnectionFlags(G_DBUS_CONNECTION_FLAGS_AUTHENTICATION_CLIENT |
                           G_DBUS_CONNECTION_FLAGS_MESSAGE_BUS_CONNECTION),
      nullptr, nullptr, &error);
  if (!connection) {
    failure = error ? error->message : "no connection";
    if (error) g_error_free(error);
  }
  return Connection(connection);
}

Variant callSync(GDBusConnection* connection, const char* destination, const char* path,
                 const char* interface, const char* method, GVariant* parameters,
                 const char* replyType, int timeoutMs) {
  return Variant(g_dbus_connection_call_sync(connection, destination, path, interface, method,
                                             parameters, G_VARIANT_TYPE(replyType),
                                             G_DBUS_CALL_FLAGS_NONE, timeoutMs, nullptr, nullptr));
}

bool portalRunning(GDBusConnection* bus) {
  const Variant owned =
      callSync(bus, "org.freedesktop.DBus", "/org/freedesktop/DBus", "org.freedesktop.DBus",
               "NameHasOwner", g_variant_new("(s)", kPortal), "(b)", kFindTimeoutMs);
  gboolean has = FALSE;
  if (owned) g_variant_get(owned.get(), "(b)", &has);
  return has;
}

bool portalActivatable(GDBusConnection* bus) {
  const Variant names =
      callSync(bus, "org.freedesktop.DBus", "/org/freedesktop/DBus", "org.freedesktop.DBus",
               "ListActivatableNames", nullptr, "(as)", kFindTimeoutMs);
  if (!names) return false;
  GVariantIter* iterator = nullptr;
  g_variant_get(names.get(), "(as)", &iterator);
  bool found = false;
  const gchar* name = nullptr;
  while (g_variant_iter_loop(iterator, "&s", &name))
    if (std::string(name) == kPortal) found = true;
  g_variant_iter_free(iterator);
  return found;
}

// A running portal that has no file chooser behind it (no backend for it) answers no version.
bool offersFileChooser(GDBusConnection* bus) {
  return bool(callSync(bus, kPortal, kPortalPath, "org.freedesktop.DBus.Properties", "Get",
                       g_variant_new("(ss)", kFileChooser, "version"), "(v)", kFindTimeoutMs));
}

// One dialog, on the worker's own main context.
struct Dialog {
  GMainContext* context = nullptr;
  GMainLoop* loop = nullptr;
  GDBusConnection* bus = nullptr;
  GCancellable* cancellable = nullptr;
  std::string handle;  // the Request's object path
  guint subscription = 0;
  bool calling = false;  // OpenFile/SaveFile has not replied yet
  bool answered = false;
  bool cancelled = false;
  FilePicker::Picked picked;
};

std::string failed(const std::string& what) {
  return "the desktop portal " + what + "; type the path instead";
}

void onResponse(GDBusConnection*, const gchar*, const gchar*, const gchar*, const gchar*,
                GVariant* parameters, gpointer data) {
  auto& dialog = *static_cast<Dialog*>(data);
  if (!g_variant_is_of_type(parameters, G_VARIANT_TYPE("(ua{sv})"))) return;
  guint32 response = 2;
  GVariant* results = nullptr;
  g_variant_get(parameters, "(u@a{sv})", &response, &results);
  const Variant owned(results);
  dialog.answered = true;
  if (response == 0) {
    const gchar** uris = nullptr;
    if (g_variant_lookup(results, "uris", "^a&s", &uris) && uris && uris[0]) {
      gchar* path = g_filename_from_uri(uris[0], nullptr, nullptr);
      if (path)
        dialog.picked.path = path;
      else
        dialog.picked.error =
            failed(std::string("gave a file that is not on this machine (") + uris[0] + ")");
      g_free(path);
    } else {
      dialog.picked.error = failed("gave no file");
    }
    g_free(uris);
  } else if (response != 1) {  // 1: the person cancelled
    dialog.picked.error = failed("ended the dialog");
  }
  g_main_loop_quit(dialog.loop);
}

void listen(Dialog& dialog, const std::string& handle) {
  if (dialog.subscription != 0)
    g_dbus_connection_signal_unsubscribe(dialog.bus, dialog.subscription);
  dialog.handle = handle;
  dialog.subscription = g_dbus_connection_signal_subscribe(
      dialog.bus, kPortal, kRequest, "Response", handle.c_str(), nullptr, G_DBUS_SIGNAL_FLAGS_NONE,
      onResponse, &dialog, nullptr);
}

void onCalled(GObject* source, GAsyncResult* result, gpointer data) {
  auto& dialog = *static_cast<Dialog*>(data);
  dialog.calling = false;
  GError* error = nullptr;
  GVariant* reply = g_dbus_connection_call_finish(G_DBUS_CONNECTION(source), result, &error);
  if (!reply) {
    const Error owned(error);
    if (!dialog.cancelled) {
      dialog.picked.error = failed(std::string("failed: ") + error->message);
      g_main_loop_quit(dialog.loop);
    }
    return;
  }
  const Variant owned(reply);
  const gchar* handle = nullptr;
  g_variant_get(reply, "(&o)", &handle);
  // Portals before 0.9 chose the Request's path themselves.
  if (!dialog.answered && dialog.handle != handle) listen(dialog, handle);
}

gboolean onCancel(gint, GIOCondition, gpointer data) {
  auto& dialog = *static_cast<Dialog*>(data);
  dialog.cancelled = true;
  g_main_loop_quit(dialog.loop);
  return G_SOURCE_REMOVE;
}

GVariant* designFilters() {
  return g_variant_new_parsed(
      "@a(sa(us)) [('Designs', [(0, '*.curvefold.json'), (0, '*.json')]), "
      "('All files', [(0, '*')])]");
}

// OpenFile's or SaveFile's options: the token naming the Request, the filters, and where to
// start (a save also proposes the current file's name).
GVariant* dialogOptions(const std::string& token, bool save, const std::string& current) {
  GVariantBuilder options;
  g_variant_builder_init(&options, G_VARIANT_TYPE_VARDICT);
  g_variant_builder_add(&options, "{sv}", "handle_token", g_variant_new_string(token.c_str()));
  g_variant_builder_add(&options, "{sv}", "modal", g_variant_new_boolean(TRUE));
  g_variant_builder_add(&options, "{sv}", "filters", designFilters());
  if (!current.empty()) {
    const std::filesystem::path path = std::filesystem::absolute(current);
    std::error_code error;
    if (std::filesystem::is_directory(path.parent_path(), error))
      g_variant_builder_add(&options, "{sv}", "current_folder",
                            g_variant_new_bytestring(path.parent_path().c_str()));
    if (save)
      g_variant_builder_add(&options, "{sv}", "current_name",
                            g_variant_new_string(path.filename().c_str()));
  }
  return g_variant_builder_end(&options);
}

// The Request's path the portal uses for this sender and token (since portal 0.9).
std::string requestPath(GDBusConnection* bus, const std::string& token) {
  std::string sender = g_dbus_connection_get_unique_name(bus);
  if (!sender.empty() && sender[0] == ':') sender.erase(0, 1);
  for (char& c : sender)
    if (c == '.') c = '_';
  return std::string(kPortalPath) + "/request/" + sender + "/" + token;
}

FilePicker::Picked askPortal(const std::string& address, bool save, const std::string& current,
                             int cancel) {
  static std::atomic<unsigned> requests{0};
  Dialog dialog;
  dialog.context = g_main_context_new();
  g_main_context_push_thread_default(dialog.context);
  std::string failure;
  const Connection bus = openBus(address, failure);
  if (!bus) {
    dialog.picked.error = failed("is out of reach (" + failure + ")");
  } else {
    dialog.bus = bus.get();
    dialog.loop = g_main_loop_new(dialog.context, FALSE);
    dialog.cancellable = g_cancellable_new();
    const std::string token =
        "curvefold" + std::to_string(::getpid()) + "_" + std::to_string(++requests);
    listen(dialog, requestPath(bus.get(), token));
    GSource* stop = g_unix_fd_source_new(cancel, G_IO_IN);
    g_source_set_callback(stop, G_SOURCE_FUNC(onCancel), &dialog, nullptr);
    g_source_attach(stop, dialog.context);
    dialog.calling = true;
    g_dbus_connection_call(
        bus.get(), kPortal, kPortalPath, kFileChooser, save ? "SaveFile" : "OpenFile",
        g_variant_new("(ss@a{sv})", "", save ? "Save the design as" : "Open a design",
                      dialogOptions(token, save, current)),
        G_VARIANT_TYPE("(o)"), G_DBUS_CALL_FLAGS_NONE, -1, dialog.cancellable, onCalled, &dialog);
    g_main_loop_run(dialog.loop);
    if (dialog.cancelled && !dialog.answered) {
      // The window is closing: the dialog goes with it.
      g_cancellable_cancel(dialog.cancellable);
      callSync(bus.get(), kPortal, dialog.handle.c_str(), kRequest, "Close", nullptr, "()",
               kFindTimeoutMs);
    }
    // The call's own callback runs before the dialog's state goes.
    while (dialog.calling) g_main_context_iteration(dialog.context, TRUE);
    g_dbus_connection_signal_unsubscribe(bus.get(), dialog.subscription);
    g_source_destroy(stop);
    g_source_unref(stop);
    g_dbus_connection_close_sync(bus.get(), nullptr, nullptr);
    g_object_unref(dialog.cancellable);
    g_main_loop_unref(dialog.loop);
  }
  g_main_context_pop_thread_default(dialog.context);
  g_main_context_unref(dialog.context);
  if (dialog.cancelled) return {};  // nobody reads it
  return dialog.picked;
}

}  // namespace

std::string PortalPicker::find() {
  const std::string address = sessionBusAddress();
  if (address.empty()) return "";
  std::string failure;
  const Connection bus = openBus(address, failure);
  if (!bus) return "";
  const bool found =
      portalRunning(bus.get()) ? offersFileChooser(bus.get()) : portalActivatable(bus.get());
  g_dbus_connection_close_sync(bus.get(), nullptr, nullptr);
  return found ? address : "";
}

void PortalPicker::start(bool save, const std::string& current) {
  if (busy()) return;
  launch([address = address_, save, current](int cancel) {
    return askPortal(address, save, current, cancel);
  });
}

// Here beside the portal, not in file_picker.cpp: only what links GDBus (curvefold_panel) may
// choose it, so the studio library below stays free of GLib.
std::unique_ptr<FilePicker> FilePicker::find() {
  if (std::string bus = PortalPicker::find(); !bus.empty())
    return std::make_unique<PortalPicker>(std::move(bus));
  if (std::string program = ZenityPicker::find(); !program.empty())
    return std::make_unique<ZenityPicker>(std::move(program));
  return nullptr;
}

}  // namespace curvefold::studio
