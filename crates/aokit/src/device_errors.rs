//! Device loss and running out of GPU memory, answered as [`AoError`]s rather than panics or
//! silently broken frames.
//!
//! wgpu reports neither where it happens: a lost device turns every later call into a no-op
//! (its errors go to the device's lost callback, not to error scopes), and an allocation that
//! does not fit is an error for the innermost error scope, else for the uncaptured-error
//! handler, which panics by default.

use std::sync::{Arc, Mutex, PoisonError};

use crate::AoError;

/// Why the device was lost, once its lost callback ran; shared between the callback and the
/// code that checks it ([`AoPipeline`](crate::AoPipeline) keeps one, and so can other GPU work
/// on the device, such as a peer's passes).
///
/// ```no_run
/// # fn f(device: &wgpu::Device) {
/// use aokit::{AoError, DeviceLoss};
/// let loss = DeviceLoss::watch(device);
/// assert!(loss.check().is_ok());
/// device.destroy();
/// // wgpu runs the callback while polling, once the queue is idle.
/// device.poll(wgpu::PollType::wait_indefinitely()).ok();
/// assert!(matches!(loss.check(), Err(AoError::DeviceLost { .. })));
/// # }
/// ```
#[derive(Clone, Debug, Default)]
pub struct DeviceLoss(Arc<Mutex<Option<String>>>);

impl DeviceLoss {
    /// A record that `device`'s lost callback fills. A device has one lost callback: this
    /// replaces any set before.
    ///
    /// ```no_run
    /// # fn f(device: &wgpu::Device) {
    /// let loss = aokit::DeviceLoss::watch(device);
    /// assert!(loss.check().is_ok(), "a device just watched is not lost");
    /// # }
    /// ```
    pub fn watch(device: &wgpu::Device) -> Self {
        let loss = Self::default();
        device.set_device_lost_callback(loss.callback());
        loss
    }

    /// A lost callback that records into `self`, for renderers that forward from their own.
    ///
    /// ```
    /// let loss = aokit::DeviceLoss::default();
    /// (loss.callback())(wgpu::DeviceLostReason::Destroyed, "gone".into());
    /// assert_eq!(loss.check().unwrap_err().to_string(), aokit::AoError::DeviceLost {
    ///     reason: "destroyed: gone".into()
    /// }.to_string());
    /// ```
    pub fn callback(&self) -> impl Fn(wgpu::DeviceLostReason, String) + Send + 'static {
        let loss = self.0.clone();
        move |reason, message| {
            let reason = match reason {
                wgpu::DeviceLostReason::Destroyed => "destroyed".to_string(),
                wgpu::DeviceLostReason::Unknown => "unknown reason".to_string(),
            };
            let reason = if message.is_empty() {
                reason
            } else {
                format!("{reason}: {message}")
            };
            *loss.lock().unwrap_or_else(PoisonError::into_inner) = Some(reason);
        }
    }

    /// [`AoError::DeviceLost`] once the device was lost.
    ///
    /// ```
    /// let loss = aokit::DeviceLoss::default();
    /// assert!(loss.check().is_ok());
    /// ```
    pub fn check(&self) -> Result<(), AoError> {
        match &*self.0.lock().unwrap_or_else(PoisonError::into_inner) {
            Some(reason) => Err(AoError::DeviceLost {
                reason: reason.clone(),
            }),
            None => Ok(()),
        }
    }
}

/// Runs `allocate` with out-of-memory errors captured, and answers one with
/// [`AoError::OutOfMemory`] naming `what`. Other errors go where they went before.
pub(crate) fn allocating<T>(
    device: &wgpu::Device,
    what: impl FnOnce() -> String,
    allocate: impl FnOnce() -> T,
) -> Result<T, AoError> {
    let scope = device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
    let made = allocate();
    out_of_memory(pollster::block_on(scope.pop()), what)?;
    Ok(made)
}

/// The error an out-of-memory scope popped with `error` answers.
fn out_of_memory(error: Option<wgpu::Error>, what: impl FnOnce() -> String) -> Result<(), AoError> {
    match error {
        None => Ok(()),
        // The scope's filter lets out-of-memory errors alone through.
        Some(_) => Err(AoError::OutOfMemory { what: what() }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An allocation that fails for want of memory cannot be provoked reliably on a test
    /// machine, so the mapping from wgpu's error is tested on an error made by hand.
    #[test]
    fn an_out_of_memory_error_names_what_was_being_made() {
        let error = wgpu::Error::OutOfMemory {
            source: "vkAllocateMemory failed".into(),
        };
        let answer = out_of_memory(Some(error), || "the textures of a 64x32 frame".into());
        assert_eq!(
            answer,
            Err(AoError::OutOfMemory {
                what: "the textures of a 64x32 frame".into()
            })
        );
        let message = answer.unwrap_err().to_string();
        assert!(
            message.contains("out of GPU memory") && message.contains("64x32"),
            "{message}"
        );
        assert_eq!(out_of_memory(None, || unreachable!()), Ok(()));
    }

    #[test]
    fn the_lost_callback_records_the_reason_for_the_next_check() {
        let loss = DeviceLoss::default();
        assert_eq!(loss.check(), Ok(()));
        (loss.callback())(wgpu::DeviceLostReason::Unknown, "driver reset".into());
        assert_eq!(
            loss.check(),
            Err(AoError::DeviceLost {
                reason: "unknown reason: driver reset".into()
            })
        );
    }
}
