//! What the runtime needs on the web (`wasm32`) only: a one-shot channel that a wgpu callback
//! (`map_async`) completes and an `async` caller awaits, since nothing may block in a page.
//!
//! Guarantee: the receiver resolves exactly once, with the value sent, or with `None` when the
//! sender was dropped unsent (wgpu dropped the callback); it never panics.

use std::cell::RefCell;
use std::future::Future;
use std::pin::Pin;
use std::rc::Rc;
use std::task::{Context, Poll, Waker};

/// The state both halves share: the value once sent, whether the sender is gone, the waiting task.
struct Slot<T> {
    value: Option<T>,
    closed: bool,
    waker: Option<Waker>,
}

/// The sending half: [`Sender::send`] completes the receiver.
pub(crate) struct Sender<T>(Rc<RefCell<Slot<T>>>);

/// The receiving half, a future of the sent value (`None` if the sender was dropped unsent).
pub(crate) struct Receiver<T>(Rc<RefCell<Slot<T>>>);

/// A new channel.
pub(crate) fn oneshot<T>() -> (Sender<T>, Receiver<T>) {
    let slot = Rc::new(RefCell::new(Slot {
        value: None,
        closed: false,
        waker: None,
    }));
    (Sender(Rc::clone(&slot)), Receiver(slot))
}

impl<T> Sender<T> {
    /// Hands `value` to the receiver and wakes it.
    pub(crate) fn send(self, value: T) {
        self.0.borrow_mut().value = Some(value);
        // Drop wakes the receiver.
    }
}

impl<T> Drop for Sender<T> {
    fn drop(&mut self) {
        let waker = {
            let mut slot = self.0.borrow_mut();
            slot.closed = true;
            slot.waker.take()
        };
        if let Some(waker) = waker {
            waker.wake();
        }
    }
}

impl<T> Future for Receiver<T> {
    type Output = Option<T>;

    fn poll(self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<Option<T>> {
        let mut slot = self.0.borrow_mut();
        if let Some(value) = slot.value.take() {
            return Poll::Ready(Some(value));
        }
        if slot.closed {
            return Poll::Ready(None);
        }
        slot.waker = Some(cx.waker().clone());
        Poll::Pending
    }
}
