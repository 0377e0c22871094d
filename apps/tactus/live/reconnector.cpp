#include "live/reconnector.hpp"

#include <condition_variable>
#include <mutex>
#include <thread>

namespace tactus::live {

namespace {
constexpr auto kGrace = std::chrono::seconds(3);  // for a worker to leave the device library
}

struct Reconnector::State {
    std::mutex mutex;
    std::condition_variable wake;
    bool stopping = false;
    bool done = false;
    std::unique_ptr<DeviceStream> reopened;
    std::thread worker;
};

Reconnector::Reconnector(std::unique_ptr<DeviceStream> lost, Open open,
                         std::chrono::milliseconds period)
    : state_(std::make_shared<State>()) {
    state_->worker = std::thread(
        [state = state_, lost = std::move(lost), open = std::move(open), period]() mutable {
            lost.reset();
            std::unique_lock lock(state->mutex);
            while (!state->stopping) {
                lock.unlock();
                std::unique_ptr<DeviceStream> stream;
                try {
                    stream = open();
                } catch (const std::exception&) {
                }
                lock.lock();
                if (stream && state->stopping) {  // back too late: the caller has moved on
                    lock.unlock();
                    stream.reset();
                    lock.lock();
                }
                if (stream) {
                    state->reopened = std::move(stream);
                    break;
                }
                state->wake.wait_for(lock, period, [&] { return state->stopping; });
            }
            state->done = true;
            state->wake.notify_all();
        });
}

Reconnector::~Reconnector() {
    std::unique_lock lock(state_->mutex);
    state_->stopping = true;
    state_->wake.notify_all();
    const bool left = state_->wake.wait_for(lock, kGrace, [&] { return state_->done; });
    lock.unlock();
    if (left)
        state_->worker.join();
    else
        state_->worker.detach();  // blocked in the device library for good
}

std::unique_ptr<DeviceStream> Reconnector::take() {
    const std::lock_guard lock(state_->mutex);
    return std::move(state_->reopened);
}

}  // namespace tactus::live
