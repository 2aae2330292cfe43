"""The patient kernel-channel wait: a message that never woke the poll is read; silence probes the kernel."""

import asyncio
from queue import Empty

import pytest

from roadnoise_utils.repro.kernel_client import _Watch, patient_get_msg


class FakeChannel:
    """A channel whose polls see nothing until ``ready_after`` polls (a lost wake-up), then one message."""

    def __init__(self, ready_after: float):
        self.ready_after, self.polls, self.timeouts = ready_after, 0, []

    async def get_msg(self, timeout=None):
        self.polls += 1
        self.timeouts.append(timeout)
        if self.polls > self.ready_after:
            return {"msg_type": "execute_reply"}
        await asyncio.sleep(timeout or 0.0)
        raise Empty


def test_a_pending_message_is_read_within_a_slice_of_a_long_wait():
    channel, probes = FakeChannel(ready_after=3), []
    patient_get_msg(channel, _Watch(), lambda: probes.append(1), poll_slice=0.01, probe_after=60.0)
    msg = asyncio.run(channel.get_msg(timeout=300.0))
    assert msg["msg_type"] == "execute_reply"
    assert channel.polls == 4 and max(channel.timeouts) <= 0.01
    assert probes == []


def test_silence_probes_the_kernel_and_a_timeout_still_raises():
    channel, probes = FakeChannel(ready_after=float("inf")), []
    watch = _Watch()
    patient_get_msg(channel, watch, lambda: probes.append(1), poll_slice=0.01, probe_after=0.03)
    with pytest.raises(Empty):
        asyncio.run(channel.get_msg(timeout=0.2))
    assert 2 <= len(probes) == watch.probes <= 8  # one per 0.03 s of silence
    assert channel.timeouts[-1] < 0.01 + 1e-9  # the last poll ends at the deadline
