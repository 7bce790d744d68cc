//! Instance and device creation, device selection and the validation-layer plumbing.
use super::error::{vk_err, GpuError, Result};
use ash::vk;
use gpu_allocator::vulkan::{Allocator, AllocatorCreateDesc};
use std::ffi::{c_void, CStr};
use std::sync::{Arc, Mutex};

const VALIDATION_LAYER: &CStr = c"VK_LAYER_KHRONOS_validation";

/// Facts about the selected device that kernels and callers need.
#[derive(Debug, Clone)]
pub struct DeviceInfo {
    pub name: String,
    pub device_type: String,
    pub api_version: String,
    pub driver: String,
    pub subgroup_size: u32,
    /// Smallest subgroup a kernel may run with (VK_EXT_subgroup_size_control), else
    /// `subgroup_size`; kernels see it as specialization constant 1.
    pub min_subgroup_size: u32,
    /// Native `atomicAdd` on float storage buffers; without it the `_cas` kernel variants are used.
    pub float_atomics: bool,
    pub max_storage_buffer_range: u64,
    /// Largest texel buffer view, in texels.
    pub max_texel_buffer_elements: u32,
    pub max_shared_memory: u32,
    pub timestamp_period_ns: f32,
    pub validation: bool,
}

pub(crate) struct Shared {
    /// Keeps the Vulkan loader library loaded while the device lives.
    pub _entry: ash::Entry,
    pub instance: ash::Instance,
    pub device: ash::Device,
    pub queue: Mutex<vk::Queue>,
    pub queue_family: u32,
    pub allocator: Mutex<Option<Allocator>>,
    pub push_descriptor: ash::khr::push_descriptor::Device,
    pub debug_device: Option<ash::ext::debug_utils::Device>,
    debug_instance: Option<(ash::ext::debug_utils::Instance, vk::DebugUtilsMessengerEXT)>,
    messages: *mut Mutex<Vec<String>>,
    pub info: DeviceInfo,
}

// SAFETY: the raw pointer is a leaked Box owned by `Shared`, only dereferenced through a Mutex.
unsafe impl Send for Shared {}
// SAFETY: as above; all other fields are Send + Sync handles or behind Mutexes.
unsafe impl Sync for Shared {}

impl Shared {
    /// Names a Vulkan object so that validation messages say which one is meant.
    pub fn name_object<H: vk::Handle>(&self, handle: H, name: &str) {
        if let Some(dd) = &self.debug_device {
            let Ok(cname) = std::ffi::CString::new(name) else {
                return;
            };
            let info = vk::DebugUtilsObjectNameInfoEXT::default()
                .object_handle(handle)
                .object_name(&cname);
            // SAFETY: the handle belongs to this device; naming is best effort.
            let _ = unsafe { dd.set_debug_utils_object_name(&info) };
        }
    }

    /// Drains the validation messages gathered so far.
    pub fn take_messages(&self) -> Vec<String> {
        // SAFETY: `messages` lives until `Shared` is dropped.
        let m = unsafe { &*self.messages };
        std::mem::take(&mut *m.lock().unwrap_or_else(|e| e.into_inner()))
    }
}

impl Drop for Shared {
    fn drop(&mut self) {
        // SAFETY: teardown order: idle, allocator, device, messenger, instance; nothing is in flight.
        unsafe {
            let _ = self.device.device_wait_idle();
            drop(
                self.allocator
                    .lock()
                    .unwrap_or_else(|e| e.into_inner())
                    .take(),
            );
            self.device.destroy_device(None);
            if let Some((di, m)) = self.debug_instance.take() {
                di.destroy_debug_utils_messenger(m, None);
            }
            self.instance.destroy_instance(None);
            drop(Box::from_raw(self.messages));
        }
    }
}

/// A Vulkan device ready for compute. Cheap to clone.
#[derive(Clone)]
pub struct Context {
    pub(crate) shared: Arc<Shared>,
}

unsafe extern "system" fn on_message(
    severity: vk::DebugUtilsMessageSeverityFlagsEXT,
    _types: vk::DebugUtilsMessageTypeFlagsEXT,
    data: *const vk::DebugUtilsMessengerCallbackDataEXT<'_>,
    user: *mut c_void,
) -> vk::Bool32 {
    // SAFETY: the layer passes valid callback data; `user` is our leaked Mutex.
    let (id, msg) = unsafe {
        let d = &*data;
        let id = if d.p_message_id_name.is_null() {
            "".into()
        } else {
            CStr::from_ptr(d.p_message_id_name).to_string_lossy()
        };
        let msg = if d.p_message.is_null() {
            "".into()
        } else {
            CStr::from_ptr(d.p_message).to_string_lossy()
        };
        (id.into_owned(), msg.into_owned())
    };
    // The layer's shader-cache notice is not about our use of the API.
    if id.contains("cache-file-error") || id.starts_with("Loader") {
        return vk::FALSE;
    }
    let line = format!("[{severity:?}] {id}: {msg}");
    eprintln!("vulkan validation: {line}");
    // SAFETY: see above.
    let m = unsafe { &*(user as *const Mutex<Vec<String>>) };
    m.lock().unwrap_or_else(|e| e.into_inner()).push(line);
    vk::FALSE
}

fn env_flag(name: &str) -> Option<bool> {
    crate::util::env_var(name).map(|v| !matches!(v.trim(), "" | "0" | "false" | "no" | "off"))
}

fn type_rank(t: vk::PhysicalDeviceType) -> u32 {
    match t {
        vk::PhysicalDeviceType::DISCRETE_GPU => 0,
        vk::PhysicalDeviceType::INTEGRATED_GPU => 1,
        vk::PhysicalDeviceType::VIRTUAL_GPU => 2,
        vk::PhysicalDeviceType::CPU => 3,
        _ => 4,
    }
}

impl Context {
    /// Opens the best device: `DREAMSCENE_DEVICE` (a name substring or an index) if set, else the
    /// first discrete GPU, then integrated, virtual, and finally a CPU device such as lavapipe.
    ///
    /// The Khronos validation layer is on in debug builds and tests (`DREAMSCENE_VALIDATION=0/1`
    /// overrides); if it is wanted but not installed this fails when `DREAMSCENE_REQUIRE_VALIDATION=1`.
    pub fn new() -> Result<Self> {
        Self::open(None)
    }

    /// As [`Context::new`], but kernels are built for subgroups as small as `n` (never larger than
    /// the device's own minimum): tests use it to run the general paths that devices with small
    /// subgroups take.
    pub fn with_min_subgroup_size(n: u32) -> Result<Self> {
        Self::open(Some(n))
    }

    fn open(min_subgroup: Option<u32>) -> Result<Self> {
        let want_validation = env_flag("DREAMSCENE_VALIDATION").unwrap_or(cfg!(debug_assertions));
        let require_validation = env_flag("DREAMSCENE_REQUIRE_VALIDATION").unwrap_or(false);
        let selector = crate::util::env_var("DREAMSCENE_DEVICE");
        Self::create(
            want_validation,
            require_validation,
            selector.as_deref(),
            min_subgroup,
        )
    }

    fn create(
        want_validation: bool,
        require_validation: bool,
        selector: Option<&str>,
        min_subgroup: Option<u32>,
    ) -> Result<Self> {
        // SAFETY: loading the system Vulkan loader.
        let entry = unsafe { ash::Entry::load() }.map_err(|e| GpuError::Loader(e.to_string()))?;
        // SAFETY: plain queries on a loaded entry.
        let layers = unsafe { entry.enumerate_instance_layer_properties() }
            .map_err(vk_err("vkEnumerateInstanceLayerProperties"))?;
        let has_layer = layers
            .iter()
            .any(|l| l.layer_name_as_c_str().is_ok_and(|n| n == VALIDATION_LAYER));
        if want_validation && !has_layer {
            if require_validation {
                return Err(GpuError::NoDevice(
                    "the Khronos validation layer is required but not installed (apt-get install vulkan-validationlayers)".into(),
                ));
            }
            eprintln!("warning: Vulkan validation layer not installed; running without it");
        }
        let validation = want_validation && has_layer;

        let app = vk::ApplicationInfo::default()
            .application_name(c"dreamscene")
            .api_version(vk::API_VERSION_1_2);
        let layer_names = [VALIDATION_LAYER.as_ptr()];
        let ext_names = [ash::ext::debug_utils::NAME.as_ptr()];
        let enables = [vk::ValidationFeatureEnableEXT::SYNCHRONIZATION_VALIDATION];
        let mut vfeatures =
            vk::ValidationFeaturesEXT::default().enabled_validation_features(&enables);
        let mut ici = vk::InstanceCreateInfo::default().application_info(&app);
        if validation {
            ici = ici
                .enabled_layer_names(&layer_names)
                .enabled_extension_names(&ext_names)
                .push_next(&mut vfeatures);
        }
        // SAFETY: create info points at live locals.
        let instance =
            unsafe { entry.create_instance(&ici, None) }.map_err(vk_err("vkCreateInstance"))?;

        let messages: *mut Mutex<Vec<String>> = Box::into_raw(Box::new(Mutex::new(Vec::new())));
        let debug_instance = if validation {
            let di = ash::ext::debug_utils::Instance::new(&entry, &instance);
            let mci = vk::DebugUtilsMessengerCreateInfoEXT::default()
                .message_severity(
                    vk::DebugUtilsMessageSeverityFlagsEXT::WARNING
                        | vk::DebugUtilsMessageSeverityFlagsEXT::ERROR,
                )
                .message_type(
                    vk::DebugUtilsMessageTypeFlagsEXT::GENERAL
                        | vk::DebugUtilsMessageTypeFlagsEXT::VALIDATION
                        | vk::DebugUtilsMessageTypeFlagsEXT::PERFORMANCE,
                )
                .pfn_user_callback(Some(on_message))
                .user_data(messages as *mut c_void);
            // SAFETY: the callback and user data outlive the messenger (destroyed in Shared::drop).
            let m = unsafe { di.create_debug_utils_messenger(&mci, None) }
                .map_err(vk_err("vkCreateDebugUtilsMessengerEXT"))?;
            Some((di, m))
        } else {
            None
        };

        let cleanup =
            |di: Option<(ash::ext::debug_utils::Instance, vk::DebugUtilsMessengerEXT)>| {
                // SAFETY: nothing else was created from the instance yet.
                unsafe {
                    if let Some((di, m)) = di {
                        di.destroy_debug_utils_messenger(m, None);
                    }
                    instance.destroy_instance(None);
                    drop(Box::from_raw(messages));
                }
            };

        let physical = match select_device(&instance, selector) {
            Ok(p) => p,
            Err(e) => {
                cleanup(debug_instance);
                return Err(e);
            }
        };
        match open_device(instance.clone(), physical) {
            Ok((device, queue_family, info, push_descriptor, float_atomics)) => {
                let debug_device =
                    validation.then(|| ash::ext::debug_utils::Device::new(&instance, &device));
                // SAFETY: the queue family was requested at device creation.
                let queue = unsafe { device.get_device_queue(queue_family, 0) };
                let allocator = Allocator::new(&AllocatorCreateDesc {
                    instance: instance.clone(),
                    device: device.clone(),
                    physical_device: physical,
                    debug_settings: Default::default(),
                    buffer_device_address: false,
                    allocation_sizes: Default::default(),
                })
                .map_err(|e| GpuError::NoDevice(format!("gpu-allocator: {e}")))?;
                let mut info = info;
                debug_assert_eq!(
                    info.float_atomics, float_atomics,
                    "the device info and the enabled features disagree on float atomics"
                );
                info.validation = validation;
                if let Some(n) = min_subgroup {
                    info.min_subgroup_size = info.min_subgroup_size.min(n.max(1));
                }
                let shared = Shared {
                    _entry: entry,
                    instance,
                    device,
                    queue: Mutex::new(queue),
                    queue_family,
                    allocator: Mutex::new(Some(allocator)),
                    push_descriptor,
                    debug_device,
                    debug_instance,
                    messages,
                    info,
                };
                Ok(Context {
                    shared: Arc::new(shared),
                })
            }
            Err(e) => {
                cleanup(debug_instance);
                Err(e)
            }
        }
    }

    /// The selected device.
    pub fn info(&self) -> &DeviceInfo {
        &self.shared.info
    }

    /// Fails with every validation message seen since the last call, if any.
    pub fn check_validation(&self) -> Result<()> {
        let m = self.shared.take_messages();
        if m.is_empty() {
            Ok(())
        } else {
            Err(GpuError::Validation(m))
        }
    }

    /// Lists all Vulkan devices (name, type) without opening one, for `doctor`.
    pub fn list_devices() -> Result<Vec<(String, String)>> {
        // SAFETY: loader + instance used only for queries and destroyed here.
        unsafe {
            let entry = ash::Entry::load().map_err(|e| GpuError::Loader(e.to_string()))?;
            let app = vk::ApplicationInfo::default().api_version(vk::API_VERSION_1_2);
            let instance = entry
                .create_instance(
                    &vk::InstanceCreateInfo::default().application_info(&app),
                    None,
                )
                .map_err(vk_err("vkCreateInstance"))?;
            let out = instance
                .enumerate_physical_devices()
                .map_err(vk_err("vkEnumeratePhysicalDevices"))?
                .into_iter()
                .map(|p| {
                    let props = instance.get_physical_device_properties(p);
                    (
                        props
                            .device_name_as_c_str()
                            .map(|c| c.to_string_lossy().into_owned())
                            .unwrap_or_default(),
                        format!("{:?}", props.device_type),
                    )
                })
                .collect();
            instance.destroy_instance(None);
            Ok(out)
        }
    }
}

fn select_device(instance: &ash::Instance, selector: Option<&str>) -> Result<vk::PhysicalDevice> {
    // SAFETY: queries on a live instance.
    let devices = unsafe { instance.enumerate_physical_devices() }
        .map_err(vk_err("vkEnumeratePhysicalDevices"))?;
    let mut named: Vec<(vk::PhysicalDevice, String, vk::PhysicalDeviceType)> = devices
        .iter()
        .map(|&p| {
            // SAFETY: as above.
            let props = unsafe { instance.get_physical_device_properties(p) };
            let name = props
                .device_name_as_c_str()
                .map(|c| c.to_string_lossy().into_owned())
                .unwrap_or_default();
            (p, name, props.device_type)
        })
        .collect();
    if named.is_empty() {
        return Err(GpuError::NoDevice(
            "the Vulkan loader found no device (install mesa-vulkan-drivers for the lavapipe CPU device)".into(),
        ));
    }
    if let Some(sel) = selector {
        if let Ok(i) = sel.trim().parse::<usize>() {
            return named.get(i).map(|d| d.0).ok_or_else(|| {
                GpuError::NoDevice(format!(
                    "DREAMSCENE_DEVICE={sel}: only {} device(s) present",
                    named.len()
                ))
            });
        }
        let low = sel.to_lowercase();
        return named
            .iter()
            .find(|d| d.1.to_lowercase().contains(&low))
            .map(|d| d.0)
            .ok_or_else(|| {
                let names: Vec<&str> = named.iter().map(|d| d.1.as_str()).collect();
                GpuError::NoDevice(format!("DREAMSCENE_DEVICE={sel} matches none of {names:?}"))
            });
    }
    named.sort_by_key(|d| type_rank(d.2));
    Ok(named[0].0)
}

type Opened = (
    ash::Device,
    u32,
    DeviceInfo,
    ash::khr::push_descriptor::Device,
    bool,
);

fn open_device(instance: ash::Instance, physical: vk::PhysicalDevice) -> Result<Opened> {
    // SAFETY: queries on a live physical device.
    let (props, sg, exts, qfams, af) = unsafe {
        let mut sg = vk::PhysicalDeviceSubgroupProperties::default();
        let mut drv = vk::PhysicalDeviceDriverProperties::default();
        let mut ssc = vk::PhysicalDeviceSubgroupSizeControlProperties::default();
        let exts = instance
            .enumerate_device_extension_properties(physical)
            .map_err(vk_err("vkEnumerateDeviceExtensionProperties"))?;
        // Queried through the extension (the instance asks for Vulkan 1.2, so 1.3 core
        // structures are off limits); without it, subgroupSize is the only size.
        let has_ssc = exts.iter().any(|e| {
            e.extension_name_as_c_str()
                .is_ok_and(|n| n == ash::ext::subgroup_size_control::NAME)
        });
        let mut p2 = vk::PhysicalDeviceProperties2::default()
            .push_next(&mut sg)
            .push_next(&mut drv);
        if has_ssc {
            p2 = p2.push_next(&mut ssc);
        }
        instance.get_physical_device_properties2(physical, &mut p2);
        let props = p2.properties;
        let min_sg = if has_ssc && ssc.min_subgroup_size > 0 {
            ssc.min_subgroup_size.min(sg.subgroup_size)
        } else {
            sg.subgroup_size
        };
        let qfams = instance.get_physical_device_queue_family_properties(physical);
        let has_af = exts.iter().any(|e| {
            e.extension_name_as_c_str()
                .is_ok_and(|n| n == ash::ext::shader_atomic_float::NAME)
        });
        let mut af = vk::PhysicalDeviceShaderAtomicFloatFeaturesEXT::default();
        if has_af {
            let mut f2 = vk::PhysicalDeviceFeatures2::default().push_next(&mut af);
            instance.get_physical_device_features2(physical, &mut f2);
        }
        let af_ok = has_af && af.shader_buffer_float32_atomic_add == vk::TRUE;
        let sg_copy = (
            (sg.subgroup_size, min_sg),
            sg.supported_stages,
            sg.supported_operations,
        );
        let drv_name = drv
            .driver_info_as_c_str()
            .map(|c| c.to_string_lossy().into_owned())
            .unwrap_or_default();
        (props, (sg_copy, drv_name), exts, qfams, af_ok)
    };
    let (((subgroup_size, min_subgroup_size), sg_stages, sg_ops), driver) = sg;
    let name = props
        .device_name_as_c_str()
        .map(|c| c.to_string_lossy().into_owned())
        .unwrap_or_default();
    let need_ops = vk::SubgroupFeatureFlags::BASIC
        | vk::SubgroupFeatureFlags::VOTE
        | vk::SubgroupFeatureFlags::ARITHMETIC
        | vk::SubgroupFeatureFlags::BALLOT
        | vk::SubgroupFeatureFlags::SHUFFLE;
    if !sg_stages.contains(vk::ShaderStageFlags::COMPUTE) || !sg_ops.contains(need_ops) {
        return Err(GpuError::NoDevice(format!(
            "`{name}` lacks compute subgroup operations (basic, vote, arithmetic, ballot, shuffle)"
        )));
    }
    if vk::api_version_minor(props.api_version) < 2 && vk::api_version_major(props.api_version) == 1
    {
        return Err(GpuError::NoDevice(format!(
            "`{name}` supports only Vulkan {}.{}; 1.2 is needed",
            vk::api_version_major(props.api_version),
            vk::api_version_minor(props.api_version)
        )));
    }
    if !(4..=128).contains(&subgroup_size) {
        return Err(GpuError::NoDevice(format!(
            "`{name}` has subgroup size {subgroup_size}; 4 to 128 supported"
        )));
    }
    let has_push = exts.iter().any(|e| {
        e.extension_name_as_c_str()
            .is_ok_and(|n| n == ash::khr::push_descriptor::NAME)
    });
    if !has_push {
        return Err(GpuError::NoDevice(format!(
            "`{name}` lacks VK_KHR_push_descriptor"
        )));
    }
    let queue_family = qfams
        .iter()
        .position(|q| q.queue_flags.contains(vk::QueueFlags::COMPUTE))
        .ok_or_else(|| GpuError::NoDevice(format!("`{name}` has no compute queue")))?
        as u32;
    let timestamps = qfams[queue_family as usize].timestamp_valid_bits > 0
        && props.limits.timestamp_compute_and_graphics == vk::TRUE;

    let prio = [1.0f32];
    let qci = [vk::DeviceQueueCreateInfo::default()
        .queue_family_index(queue_family)
        .queue_priorities(&prio)];
    let mut dev_exts = vec![ash::khr::push_descriptor::NAME.as_ptr()];
    if af {
        dev_exts.push(ash::ext::shader_atomic_float::NAME.as_ptr());
    }
    let mut afe = vk::PhysicalDeviceShaderAtomicFloatFeaturesEXT::default()
        .shader_buffer_float32_atomic_add(true);
    let mut f12 = vk::PhysicalDeviceVulkan12Features::default().host_query_reset(true);
    let mut f2 = vk::PhysicalDeviceFeatures2::default().push_next(&mut f12);
    if af {
        f2 = f2.push_next(&mut afe);
    }
    let dci = vk::DeviceCreateInfo::default()
        .queue_create_infos(&qci)
        .enabled_extension_names(&dev_exts)
        .push_next(&mut f2);
    // SAFETY: create info points at live locals; the physical device is valid.
    let device = unsafe { instance.create_device(physical, &dci, None) }
        .map_err(vk_err("vkCreateDevice"))?;
    let push_descriptor = ash::khr::push_descriptor::Device::new(&instance, &device);
    let info = DeviceInfo {
        name,
        device_type: format!("{:?}", props.device_type),
        api_version: format!(
            "{}.{}.{}",
            vk::api_version_major(props.api_version),
            vk::api_version_minor(props.api_version),
            vk::api_version_patch(props.api_version)
        ),
        driver,
        subgroup_size,
        min_subgroup_size,
        float_atomics: af,
        max_storage_buffer_range: props.limits.max_storage_buffer_range as u64,
        max_texel_buffer_elements: props.limits.max_texel_buffer_elements,
        max_shared_memory: props.limits.max_compute_shared_memory_size,
        timestamp_period_ns: if timestamps {
            props.limits.timestamp_period
        } else {
            0.0
        },
        validation: false, // set by the caller
    };
    Ok((device, queue_family, info, push_descriptor, af))
}
