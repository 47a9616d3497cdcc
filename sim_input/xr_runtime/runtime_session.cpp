// The simulated OpenXR runtime: the session and its state machine, views and frames (the
// specification's "Session", "View Configurations" and "Rendering" chapters: xrWaitFrame,
// xrBeginFrame, xrEndFrame).
#include "sim_input/xr_runtime/runtime_state.hpp"

namespace curvefold::simxr {

XRAPI_ATTR XrResult XRAPI_CALL createSession(XrInstance handle, const XrSessionCreateInfo* info,
                                             XrSession* out) {
  return guard([&] {
    Instance& instance = instanceOf(handle);
    checkType(info, XR_TYPE_SESSION_CREATE_INFO);
    checkSystem(info->systemId);
    if (!out) return XR_ERROR_VALIDATION_FAILURE;
    auto session = std::make_unique<Session>();
    const auto* binding = static_cast<const XrBaseInStructure*>(info->next);
    if (binding && binding->type == XR_TYPE_GRAPHICS_BINDING_VULKAN2_KHR) {
      if (!instance.extensions.count("XR_KHR_vulkan_enable2")) return XR_ERROR_VALIDATION_FAILURE;
      if (!instance.requirementsCalled) return XR_ERROR_GRAPHICS_REQUIREMENTS_CALL_MISSING;
      const auto* vulkan = reinterpret_cast<const XrGraphicsBindingVulkan2KHR*>(binding);
      if (!vulkan->device || !vulkan->physicalDevice || !vulkan->instance)
        return XR_ERROR_GRAPHICS_DEVICE_INVALID;
      session->vulkan = VulkanBinding{vulkan->instance, vulkan->physicalDevice, vulkan->device,
                                      vulkan->queueFamilyIndex, vulkan->queueIndex};
    } else if (!instance.extensions.count("XR_MND_headless")) {
      return XR_ERROR_GRAPHICS_DEVICE_INVALID;
    }
    Session* created = session.release();
    instance.sessions.insert(created);
    *out = handleOf<XrSession>(created);
    setState(*created, XR_SESSION_STATE_IDLE);
    setState(*created, XR_SESSION_STATE_READY);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL destroySessionEntry(XrSession handle) {
  return guard([&] {
    Session* session = objectOf<Session>(handle);
    if (!session || !gInstance || !gInstance->sessions.count(session))
      return XR_ERROR_HANDLE_INVALID;
    destroySession(session);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL beginSession(XrSession handle, const XrSessionBeginInfo* info) {
  return guard([&] {
    Session& session = liveSessionOf(handle);
    checkType(info, XR_TYPE_SESSION_BEGIN_INFO);
    if (info->primaryViewConfigurationType != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO)
      return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    if (session.running) return XR_ERROR_SESSION_RUNNING;
    if (session.state != XR_SESSION_STATE_READY) return XR_ERROR_SESSION_NOT_READY;
    session.running = true;
    session.focusedOnce = false;
    setState(session, XR_SESSION_STATE_SYNCHRONIZED);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL endSession(XrSession handle) {
  return guard([&] {
    Session& session = liveSessionOf(handle);
    if (!session.running) return XR_ERROR_SESSION_NOT_RUNNING;
    if (session.state != XR_SESSION_STATE_STOPPING) return XR_ERROR_SESSION_NOT_STOPPING;
    saveViews(session);
    session.running = false;
    session.waited = session.begun = false;
    setState(session, XR_SESSION_STATE_IDLE);
    if (session.exitRequested) setState(session, XR_SESSION_STATE_EXITING);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL requestExitSession(XrSession handle) {
  return guard([&] {
    Session& session = liveSessionOf(handle);
    if (!session.running) return XR_ERROR_SESSION_NOT_RUNNING;
    session.exitRequested = true;
    stop(session);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL locateViews(XrSession handle, const XrViewLocateInfo* info,
                                           XrViewState* state, std::uint32_t capacity,
                                           std::uint32_t* count, XrView* views) {
  return guard([&] {
    Session& session = liveSessionOf(handle);
    checkType(info, XR_TYPE_VIEW_LOCATE_INFO);
    checkType(state, XR_TYPE_VIEW_STATE);
    Space* base = objectOf<Space>(info->space);
    if (!base) return XR_ERROR_HANDLE_INVALID;
    if (info->viewConfigurationType != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO)
      return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    if (!count) return XR_ERROR_VALIDATION_FAILURE;
    *count = 2;
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < 2) return XR_ERROR_SIZE_INSUFFICIENT;
    (void)session;
    bool valid = false;
    const Pose worldBase = locate(*gInstance, *base, valid);
    Space headSpace{&session, XR_REFERENCE_SPACE_TYPE_VIEW, nullptr, XR_NULL_PATH, Pose{}};
    bool headValid = false;
    const Pose head = locate(*gInstance, headSpace, headValid);
    for (int i = 0; i < 2; ++i) {
      checkType(&views[i], XR_TYPE_VIEW);
      const double side = i == 0 ? -0.5 : 0.5;
      const Pose eye = head * Pose{{side * kSimEyeSeparation, 0.0, 0.0}, glm::dquat(1, 0, 0, 0)};
      views[i].pose = toXr(worldBase.inverse() * eye);
      // The left eye sees further left than right (towards the nose less), the right mirrored.
      views[i].fov =
          i == 0 ? XrFovf{-0.87f, 0.79f, 0.84f, -0.91f} : XrFovf{-0.79f, 0.87f, 0.84f, -0.91f};
    }
    state->viewStateFlags =
        valid ? (XR_VIEW_STATE_POSITION_VALID_BIT | XR_VIEW_STATE_ORIENTATION_VALID_BIT |
                 XR_VIEW_STATE_POSITION_TRACKED_BIT | XR_VIEW_STATE_ORIENTATION_TRACKED_BIT)
              : 0;
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL waitFrame(XrSession handle, const XrFrameWaitInfo*,
                                         XrFrameState* state) {
  return guard([&] {
    Session& session = liveSessionOf(handle);
    checkType(state, XR_TYPE_FRAME_STATE);
    if (!session.running) return XR_ERROR_SESSION_NOT_RUNNING;
    Instance& instance = *gInstance;
    serveFrame(instance, session);
    if (instance.config.realtime)
      std::this_thread::sleep_until(instance.wallStart +
                                    std::chrono::nanoseconds(instance.time - 1'000'000'000));
    session.waited = true;
    state->predictedDisplayTime = instance.time;
    state->predictedDisplayPeriod =
        instance.config.input ? XrDuration(1e9 / std::max(instance.config.input->header.rate, 1.0))
                              : 11'111'111;
    state->shouldRender =
        session.state == XR_SESSION_STATE_VISIBLE || session.state == XR_SESSION_STATE_FOCUSED;
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL beginFrame(XrSession handle, const XrFrameBeginInfo*) {
  return guard([&] {
    Session& session = liveSessionOf(handle);
    if (!session.running) return XR_ERROR_SESSION_NOT_RUNNING;
    if (!session.waited) return XR_ERROR_CALL_ORDER_INVALID;
    session.waited = false;
    const bool discarded = session.begun;
    session.begun = true;
    return discarded ? XR_FRAME_DISCARDED : XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL endFrame(XrSession handle, const XrFrameEndInfo* info) {
  return guard([&] {
    Session& session = liveSessionOf(handle);
    checkType(info, XR_TYPE_FRAME_END_INFO);
    if (!session.running) return XR_ERROR_SESSION_NOT_RUNNING;
    if (!session.begun) return XR_ERROR_CALL_ORDER_INVALID;
    // No xrWaitFrame predicts a time at or before the epoch.
    if (info->displayTime <= 0) return XR_ERROR_TIME_INVALID;
    if (info->environmentBlendMode != XR_ENVIRONMENT_BLEND_MODE_OPAQUE)
      return XR_ERROR_ENVIRONMENT_BLEND_MODE_UNSUPPORTED;
    if (info->layerCount > 0 && !info->layers) return XR_ERROR_VALIDATION_FAILURE;
    std::uint32_t viewCount = 0, depthCount = 0;
    for (std::uint32_t i = 0; i < info->layerCount; ++i) {
      const XrCompositionLayerBaseHeader* layer = info->layers[i];
      if (!layer || layer->type != XR_TYPE_COMPOSITION_LAYER_PROJECTION)
        return XR_ERROR_LAYER_INVALID;
      const auto* projection = reinterpret_cast<const XrCompositionLayerProjection*>(layer);
      if (projection->viewCount != 2 || !projection->views || !objectOf<Space>(projection->space))
        return XR_ERROR_VALIDATION_FAILURE;
      for (std::uint32_t v = 0; v < 2; ++v) {
        const XrSwapchainSubImage& sub = projection->views[v].subImage;
        Swapchain* swapchain = objectOf<Swapchain>(sub.swapchain);
        if (!swapchain || swapchain->session != &session) return XR_ERROR_HANDLE_INVALID;
        if (swapchain->lastReleased < 0) return XR_ERROR_LAYER_INVALID;  // nothing released
        if (sub.imageRect.offset.x < 0 || sub.imageRect.offset.y < 0 ||
            sub.imageRect.extent.width <= 0 || sub.imageRect.extent.height <= 0)
          return XR_ERROR_SWAPCHAIN_RECT_INVALID;
        if (sub.imageArrayIndex >= swapchain->images->layers()) return XR_ERROR_VALIDATION_FAILURE;
        session.lastViewSwapchain[v] = {swapchain, sub.imageArrayIndex};
        ++viewCount;
        // XR_KHR_composition_layer_depth: a depth image for the view, checked as its spec says.
        for (auto* next = static_cast<const XrBaseInStructure*>(projection->views[v].next); next;
             next = next->next) {
          if (next->type != XR_TYPE_COMPOSITION_LAYER_DEPTH_INFO_KHR) continue;
          if (!gInstance || !gInstance->extensions.count("XR_KHR_composition_layer_depth"))
            return XR_ERROR_VALIDATION_FAILURE;  // a structure of an extension not enabled
          const auto* depth = reinterpret_cast<const XrCompositionLayerDepthInfoKHR*>(next);
          Swapchain* images = objectOf<Swapchain>(depth->subImage.swapchain);
          if (!images || images->session != &session) return XR_ERROR_HANDLE_INVALID;
          if (!images->images->depth() || images->lastReleased < 0) return XR_ERROR_LAYER_INVALID;
          if (depth->subImage.imageArrayIndex >= images->images->layers())
            return XR_ERROR_VALIDATION_FAILURE;
          if (depth->subImage.imageRect.extent.width <= 0 ||
              depth->subImage.imageRect.extent.height <= 0)
            return XR_ERROR_SWAPCHAIN_RECT_INVALID;
          if (!(depth->minDepth >= 0.0f && depth->minDepth <= 1.0f && depth->maxDepth >= 0.0f &&
                depth->maxDepth <= 1.0f && depth->minDepth < depth->maxDepth) ||
              !(depth->nearZ > 0.0f) || !(depth->farZ > 0.0f) || depth->nearZ == depth->farZ)
            return XR_ERROR_VALIDATION_FAILURE;
          ++depthCount;
        }
      }
    }
    session.begun = false;
    log("end_frame layers=" + std::to_string(info->layerCount) +
        " views=" + std::to_string(viewCount) + " depth=" + std::to_string(depthCount));
    if (!session.focusedOnce && session.state == XR_SESSION_STATE_SYNCHRONIZED) {
      session.focusedOnce = true;
      setState(session, XR_SESSION_STATE_VISIBLE);
      setState(session, XR_SESSION_STATE_FOCUSED);
    }
    return XR_SUCCESS;
  });
}

}  // namespace curvefold::simxr
