"""A notebook client that does not wait forever on a kernel message whose wake-up was lost.

The reproduction executes notebooks with :class:`nbclient.NotebookClient`, which waits for a
cell's ``execute_reply`` on the shell channel in one poll of up to the cell's time limit, and
for its outputs on the IOPub channel in one poll without a limit. ZeroMQ signals a socket's
readiness by an edge-triggered file descriptor: if that edge is consumed while a message is
pending (a send on the same socket, or two messages arriving together), an asyncio poll is not
woken until something else happens on the socket. In a fresh reproduction (two kernels on two
cores) this stalled a notebook for minutes at an interactive-widget cell, both the kernel and the
client idle, with ipykernel 7 (its shell replies bypass the stream that reads requests,
ipython/ipykernel#1554) and, more rarely, with ipykernel 6; the same notebooks never stalled
under nbval, whose blocking client polls the sockets directly. Related reports: jupyter/nbclient#312,
jupyter/nbconvert#2029.

:class:`PatientClient` makes both waits robust, whichever side lost the edge:

* every wait is cut into polls of :data:`POLL_SLICE` s, each of which ends with a real
  ``zmq_poll`` of the socket: a message that arrived without waking the poll is read within a
  slice;
* after :data:`PROBE_AFTER` s without any message on either channel, the kernel is sent a
  ``kernel_info_request`` on the shell channel: a request the kernel has not noticed is read with
  it (the reply, of another parent, is ignored like any other message of another request). A
  kernel busy computing answers the probe when its cell ends.
"""

from __future__ import annotations

import time
from queue import Empty

from nbclient import NotebookClient

#: Longest single poll of a kernel channel (s).
POLL_SLICE = 1.0
#: Silence on both channels (s) after which the kernel is probed with a ``kernel_info_request``.
PROBE_AFTER = 15.0


class _Watch:
    """When a message was last read from the kernel, and how many probes were sent."""

    def __init__(self) -> None:
        self.last = time.monotonic()
        self.probes = 0


def patient_get_msg(channel, watch: _Watch, probe, poll_slice: float = POLL_SLICE, probe_after: float = PROBE_AFTER):
    """Replace ``channel.get_msg`` by polls of at most ``poll_slice`` s (see the module notes).

    ``probe()`` is called after ``probe_after`` s without a message on any watched channel.
    The replacement keeps the signature ``get_msg(timeout=None)`` and raises
    :class:`queue.Empty` when ``timeout`` s pass without a message, as the original does.
    """
    original = channel.get_msg

    async def get_msg(timeout: float | None = None):
        deadline = None if timeout is None else time.monotonic() + timeout
        while True:
            left = poll_slice if deadline is None else min(poll_slice, max(0.0, deadline - time.monotonic()))
            try:
                msg = await original(timeout=left)
            except Empty:
                now = time.monotonic()
                if deadline is not None and now >= deadline:
                    raise
                if now - watch.last >= probe_after:
                    probe()
                    watch.probes += 1
                    watch.last = now
                continue
            watch.last = time.monotonic()
            return msg

    channel.get_msg = get_msg


class PatientClient(NotebookClient):
    """:class:`nbclient.NotebookClient` whose shell and IOPub waits survive a lost wake-up (module notes)."""

    async def async_start_new_kernel_client(self):
        kc = await super().async_start_new_kernel_client()
        watch = _Watch()
        self.kernel_probes = watch

        def probe() -> None:
            kc.shell_channel.send(kc.session.msg("kernel_info_request"))

        patient_get_msg(kc.shell_channel, watch, probe)
        patient_get_msg(kc.iopub_channel, watch, probe)
        return kc
