// The one-process leases against the lease contract.
import { describe } from 'vitest';
import { MemoryLeases } from '../../../server/cluster/index.ts';
import { leaseContract } from '../../contract/leases.contract.ts';

describe('MemoryLeases', () => {
  leaseContract(async () => {
    const leases = new MemoryLeases();
    return { a: leases, b: leases };
  });
});
