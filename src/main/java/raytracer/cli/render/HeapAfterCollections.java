package raytracer.cli.render;

import com.sun.management.GarbageCollectionNotificationInfo;
import java.lang.management.GarbageCollectorMXBean;
import java.lang.management.ManagementFactory;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;
import java.lang.management.MemoryUsage;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.stream.Collectors;
import javax.management.NotificationEmitter;
import javax.management.openmbean.CompositeData;

/**
 * The most heap in use right after any garbage collection of the run: what was alive then, and a
 * lower bound of the largest live set. {@link RunReport#peakHeapBytes} sums each pool's own peak,
 * garbage and the young generation's sizing included (the young pool's peak is how far it was
 * allowed to fill); this is the figure that a mesh's arrays and the transient arrays of its build
 * decide. Listened for from the start of a --stats run; the collector's notifications arrive on a
 * thread of their own, so one at the very end of the run may be missed.
 */
final class HeapAfterCollections {
    private final Set<String> heapPools;
    private final AtomicLong largest = new AtomicLong();
    private final AtomicInteger collections = new AtomicInteger();

    private HeapAfterCollections() {
        heapPools = ManagementFactory.getMemoryPoolMXBeans().stream()
            .filter(pool -> pool.getType() == MemoryType.HEAP)
            .map(MemoryPoolMXBean::getName)
            .collect(Collectors.toUnmodifiableSet());
    }

    /** Starts listening to every collector of this JVM. */
    static HeapAfterCollections start() {
        HeapAfterCollections watch = new HeapAfterCollections();
        for (GarbageCollectorMXBean collector : ManagementFactory.getGarbageCollectorMXBeans()) {
            if (collector instanceof NotificationEmitter emitter) {
                emitter.addNotificationListener((notification, handback) -> {
                    if (GarbageCollectionNotificationInfo.GARBAGE_COLLECTION_NOTIFICATION.equals(notification.getType())) {
                        watch.collected(GarbageCollectionNotificationInfo.from((CompositeData) notification.getUserData()));
                    }
                }, null, null);
            }
        }
        return watch;
    }

    private void collected(GarbageCollectionNotificationInfo info) {
        long used = 0;
        for (Map.Entry<String, MemoryUsage> pool : info.getGcInfo().getMemoryUsageAfterGc().entrySet()) {
            if (heapPools.contains(pool.getKey())) {
                used += pool.getValue().getUsed();
            }
        }
        largest.accumulateAndGet(used, Math::max);
        collections.incrementAndGet();
    }

    /** The most heap in use after a collection so far, or -1 before the first. */
    long largestBytes() {
        return collections.get() == 0 ? -1 : largest.get();
    }

    int collections() {
        return collections.get();
    }
}
