package raytracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinTask;
import java.util.concurrent.RecursiveAction;
import org.junit.jupiter.api.Test;

/**
 * The run's one pool: its size limits, work started on it stays on its threads (forks included),
 * and what the work throws comes back as it was thrown.
 */
class WorkersTest {
    @Test
    void threadCountsOutsideWhatAForkJoinPoolRunsAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> new Workers(0));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new Workers(32768));
        assertEquals("threads must be 1 to 32767, got 32768", e.getMessage());
        try (Workers most = new Workers(Workers.MAX_THREADS)) {
            assertEquals(Workers.MAX_THREADS, most.threads(), "threads start only when there is work");
        }
    }

    /** Splits down to single units and notes the pool and thread each unit ran on. */
    private static final class Tree extends RecursiveAction {
        private static final long serialVersionUID = 1L;
        private final int units;
        private final transient Set<ForkJoinPool> pools;
        private final transient Set<Thread> threads;

        Tree(int units, Set<ForkJoinPool> pools, Set<Thread> threads) {
            this.units = units;
            this.pools = pools;
            this.threads = threads;
        }

        @Override
        protected void compute() {
            if (units > 1) {
                invokeAll(new Tree(units / 2, pools, threads), new Tree(units - units / 2, pools, threads));
                return;
            }
            pools.add(getPool());
            threads.add(Thread.currentThread());
        }
    }

    @Test
    void whatACallForksRunsInThePoolOnItsThreadsAlone() throws Exception {
        for (int n : new int[] {1, 2}) {
            Set<ForkJoinPool> pools = ConcurrentHashMap.newKeySet();
            Set<Thread> threads = ConcurrentHashMap.newKeySet();
            try (Workers workers = new Workers(n)) {
                ForkJoinPool caller = workers.call(() -> {
                    new Tree(4096, pools, threads).invoke();
                    return ForkJoinTask.getPool();
                });
                assertSame(workers.pool(), caller, "the call runs on a worker");
                assertEquals(Set.of(workers.pool()), pools, "every forked unit ran in the run's pool");
                assertNotSame(ForkJoinPool.commonPool(), workers.pool());
                assertTrue(threads.size() <= n, n + " threads, yet units ran on " + threads);
                assertTrue(workers.pool().getPoolSize() <= n, "the pool grew to " + workers.pool().getPoolSize());
            }
        }
    }

    @Test
    void aCallThrowsWhatItsWorkThrew() throws Exception {
        // ForkJoinTask.join rethrows a copy of an exception thrown on another thread, its message
        // prefixed with the class name: the command line prints messages, so the original must come back
        IOException io = new IOException("cannot read scene file x.yaml: no such file");
        StackOverflowError deep = new StackOverflowError();
        try (Workers workers = new Workers(2)) {
            assertSame(io, assertThrows(IOException.class, () -> workers.call(() -> {
                throw io;
            })));
            assertSame(deep, assertThrows(StackOverflowError.class, () -> workers.call(() -> {
                throw deep;
            })));
            assertEquals("done", workers.call(() -> "done"), "the pool still works after a failed call");
        }
    }
}
