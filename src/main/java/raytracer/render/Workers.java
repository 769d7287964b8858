package raytracer.render;

import java.util.concurrent.Callable;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinTask;
import java.util.concurrent.RecursiveAction;
import java.util.concurrent.TimeUnit;

/**
 * The one fork/join pool of a run, sized by {@code --threads}: it loads the scene, builds the
 * BVHs and renders every frame of a {@code --repeat}. Work started with {@link #call} runs on one
 * of its threads, so whatever that work forks (the OBJ parser's chunks, a BVH builder's subtrees)
 * runs in this pool too: a task forked on a pool's worker goes to that pool
 * ({@link ForkJoinTask#fork}). Close it when the run ends.
 */
public final class Workers implements AutoCloseable {
    /** The most threads a {@link ForkJoinPool} runs (its parallelism limit, 2^15 - 1). */
    public static final int MAX_THREADS = 0x7fff;

    private final ForkJoinPool pool;

    public Workers(int threads) {
        if (threads < 1 || threads > MAX_THREADS) {
            throw new IllegalArgumentException("threads must be 1 to " + MAX_THREADS + ", got " + threads);
        }
        // at most `threads` threads: a worker blocked in a join may not be compensated by a spare
        // thread (the default allows 256), which would run more threads than --threads asked for;
        // the saturate predicate lets the join wait instead of throwing
        pool = new ForkJoinPool(threads, ForkJoinPool.defaultForkJoinWorkerThreadFactory, null, false,
                                0, threads, 1, p -> true, 60, TimeUnit.SECONDS);
    }

    public int threads() {
        return pool.getParallelism();
    }

    /**
     * Runs {@code work} on one of the workers and returns its result, or throws what it threw: the
     * same exception, not the copy that {@link ForkJoinTask#join} makes of an exception thrown on
     * another thread (whose message starts with the class name), so the command line can print it.
     */
    public <T> T call(Callable<T> work) throws Exception {
        Call<T> call = new Call<>(work);
        pool.invoke(call);
        if (call.failure instanceof Exception e) {
            throw e;
        }
        if (call.failure instanceof Error e) {
            throw e;
        }
        if (call.failure != null) {
            throw new IllegalStateException(call.failure);
        }
        return call.result;
    }

    /** Runs {@code task} in the pool and waits for it. */
    void invoke(ForkJoinTask<?> task) {
        pool.invoke(task);
    }

    /** The pool itself, for tests that check where work ran. */
    ForkJoinPool pool() {
        return pool;
    }

    @Override
    public void close() {
        pool.shutdown();
    }

    /** Keeps the work's own result or failure; the task itself always completes normally. */
    private static final class Call<T> extends RecursiveAction {
        private static final long serialVersionUID = 1L;
        private final transient Callable<T> work;
        private transient T result;
        private transient Throwable failure;

        Call(Callable<T> work) {
            this.work = work;
        }

        @Override
        protected void compute() {
            try {
                result = work.call();
            } catch (Throwable t) {
                failure = t;
            }
        }
    }
}
